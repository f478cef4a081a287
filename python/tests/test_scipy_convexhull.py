"""scipy's own ConvexHull tests, taken from the installed scipy, run against pqhull.ConvexHull.

scipy/spatial/tests/test_qhull.py imports Qhull's wrapper as ``qhull`` (``import
scipy.spatial._qhull as qhull``) and builds hulls with ``qhull.ConvexHull``;
test__plotutils.py does ``from scipy.spatial import ConvexHull``. Each test below is scipy's
own function (inherited or borrowed, never copied), run with those names — and
``scipy.spatial.ConvexHull`` — pointing at pqhull.ConvexHull: every TestConvexHull test, the
TestUtilities volume and area tests, and the plotting test that builds a hull.
``test_every_scipy_convexhull_test_is_here`` reads scipy's test files and fails if a test that
mentions ConvexHull is not run here, so a new scipy cannot add one unnoticed.

A test that fails because of a documented, intended difference would be listed in
EXPECTED_FAILURES with its reason and marked xfail(strict=True), so it fails the day it passes;
nothing is skipped. The list is empty: every test passes.
"""

import ast
import importlib
import inspect

import numpy as np
import pytest
import scipy.spatial
import scipy.spatial._qhull

import pqhull

scipy_qhull_tests = importlib.import_module("scipy.spatial.tests.test_qhull")
scipy_plot_tests = importlib.import_module("scipy.spatial.tests.test__plotutils")

# Test name (as pytest names it, with its parameters) -> why it fails on purpose. Empty: all of
# scipy's ConvexHull tests pass against the exact hull.
EXPECTED_FAILURES: dict[str, str] = {}


class PqhullInScipysPlace:
    """Runs each test with every ConvexHull it builds a pqhull.ConvexHull (at least one)."""

    @pytest.fixture(autouse=True)
    def pqhull_in_scipys_place(self, monkeypatch, request):
        built = []

        def convex_hull(*args, **kwargs):
            built.append(None)
            hull = pqhull.ConvexHull(*args, **kwargs)
            assert type(hull) is pqhull.ConvexHull
            return hull

        assert scipy_qhull_tests.qhull is scipy.spatial._qhull
        monkeypatch.setattr(scipy.spatial._qhull, "ConvexHull", convex_hull)
        monkeypatch.setattr(scipy.spatial, "ConvexHull", convex_hull)
        monkeypatch.setattr(scipy_plot_tests, "ConvexHull", convex_hull)
        reason = EXPECTED_FAILURES.get(request.node.name)
        if reason is not None:
            request.applymarker(pytest.mark.xfail(strict=True, reason=reason))
        yield
        assert built, "the test built no ConvexHull"


class TestConvexHull(PqhullInScipysPlace, scipy_qhull_tests.TestConvexHull):
    """scipy's TestConvexHull: every test of it, inherited with its parameters."""


class TestUtilities(PqhullInScipysPlace):
    """The volume and area tests of scipy's TestUtilities (the others test Delaunay)."""

    test_volume_area = scipy_qhull_tests.TestUtilities.test_volume_area
    test_random_volume_area = scipy_qhull_tests.TestUtilities.test_random_volume_area
    test_incremental_volume_area_random_input = (
        scipy_qhull_tests.TestUtilities.test_incremental_volume_area_random_input
    )


class TestPlotting(PqhullInScipysPlace):
    """scipy's convex_hull_plot_2d smoke test (needs matplotlib)."""

    points = scipy_plot_tests.TestPlotting.points

    def test_convex_hull(self):
        assert scipy_plot_tests.has_matplotlib, (
            "matplotlib is needed for scipy's plotting test: pip install matplotlib"
        )
        scipy_plot_tests.TestPlotting.test_convex_hull(self)


def mentions_convex_hull(node):
    return any(
        (isinstance(n, ast.Name) and n.id == "ConvexHull")
        or (isinstance(n, ast.Attribute) and n.attr == "ConvexHull")
        for n in ast.walk(node)
    )


def scipy_tests_of_convex_hull(module):
    """(class, test) of every test function in `module`'s source that mentions ConvexHull."""
    tree = ast.parse(inspect.getsource(module))
    found = set()
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            for item in node.body:
                if (isinstance(item, ast.FunctionDef) and item.name.startswith("test")
                        and mentions_convex_hull(item)):
                    found.add((node.name, item.name))
        elif (isinstance(node, ast.FunctionDef) and node.name.startswith("test")
              and mentions_convex_hull(node)):
            found.add((None, node.name))
    return found


def test_every_scipy_convexhull_test_is_here():
    here = {
        (cls.__name__, name)
        for cls in (TestConvexHull, TestUtilities, TestPlotting)
        for name in dir(cls)
        if name.startswith("test")
    }
    wanted = scipy_tests_of_convex_hull(scipy_qhull_tests) | scipy_tests_of_convex_hull(
        scipy_plot_tests
    )
    assert wanted, "found no ConvexHull test in scipy's test files"
    missing = wanted - here
    assert not missing, f"scipy tests of ConvexHull not run against pqhull: {sorted(missing)}"
    # And what runs here is scipy's code, not a copy.
    assert TestConvexHull.test_good2d is scipy_qhull_tests.TestConvexHull.test_good2d
    assert np.array_equal(TestPlotting.points, scipy_plot_tests.TestPlotting.points)
