"""Shared pytest set-up of the Python package's tests."""


def pytest_configure(config):
    # Marks of scipy's test_qhull.py (registered by scipy's own conftest, which is not loaded
    # when test_scipy_convexhull.py runs scipy's ConvexHull tests from the installed scipy).
    config.addinivalue_line("markers", "slow: scipy's mark for a slow test")
    config.addinivalue_line("markers", "fail_slow(seconds): scipy's mark for a time limit")
