//! Steady-state allocation of the grasp evaluators and of full hull builds in a hull's storage:
//! a counting global allocator (this test binary only; counts per thread, so tests running side
//! by side do not see each other's).
//!
//! After one pass over a set of grasps has grown every buffer, a second pass over the same grasps
//! must allocate nothing on grasps settled by GJK (not force closure), and on force-closure grasps
//! only the exact-arithmetic cache of the facets whose floating-point filter fails (one box per
//! such facet, dropped when the facet's slot is reused). Seen (each test prints its figures:
//! `cargo nextest run --release --features qhull --test allocation --no-capture`, 2026-12-04):
//! 3.8 per Q1 grasp at k = 32, 54.5 per Q∞ grasp (with the zero wrench) at k = 8 (the Minkowski
//! sum's exact degeneracies are not declared to the engine), 9.5 per Q_OWS grasp, 5 per
//! two-phase full build. The bounds below are tripwires: an allocation per facet or per point
//! would exceed them several times over.

// Counting allocations needs a `GlobalAlloc` impl, which is `unsafe` by definition; the library
// itself forbids unsafe code.
#![allow(unsafe_code)]

use pqhull::geometry::Rng;
use pqhull::grasp::{Evaluator, FrictionModel, Grasp, Method, Metric};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

// SAFETY: forwards every call to the system allocator unchanged; the counter is a const-initialised
// thread-local `Cell`, whose access never allocates.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.with(|n| n.set(n.get() + 1));
        // SAFETY: same layout contract as the caller's.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` was allocated by `System` with `layout`.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.with(|n| n.set(n.get() + 1));
        // SAFETY: `ptr` was allocated by `System` with `layout`.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

/// `pqh bench gws`'s grasps: 4 contacts on the 1 × 0.4 × 0.2 bar, seed 1.
fn grasps(edges: usize, count: usize) -> Vec<Grasp> {
    let mut rng = Rng::new(1);
    let friction = FrictionModel::try_new(0.5, edges).unwrap();
    (0..count)
        .map(|_| Grasp::random_on_box(&mut rng, [0.5, 0.2, 0.1], 4, friction))
        .collect()
}

/// What a grasp's evaluation did: force closure (a hull), settled without a hull (GJK), or
/// neither — a grasp within `δ` of the boundary, which the exact engine decides on the raw
/// wrenches (a hull of sliver facets whose exact caches allocate).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    ForceClosure,
    NoHull,
    Boundary,
}

fn kind(force_closure: bool, facets_created: usize) -> Kind {
    match (force_closure, facets_created) {
        (true, _) => Kind::ForceClosure,
        (false, 0) => Kind::NoHull,
        (false, _) => Kind::Boundary,
    }
}

/// Steady-state allocations of `evaluate` over `set`: a first pass grows every buffer, a second
/// is counted, split by [`Kind`]. Asserts what the file's header says — nothing for grasps GJK
/// settles, at most `per_grasp` for force-closure ones — and prints the figures
/// (`cargo nextest run --release --test allocation --no-capture`).
fn check_second_pass<G>(
    what: &str,
    set: &[G],
    per_grasp: usize,
    mut evaluate: impl FnMut(&G) -> Kind,
) {
    let kinds: Vec<Kind> = set.iter().map(&mut evaluate).collect();
    let (mut fc, mut other, mut boundary) = ((0, 0), (0, 0), (0, 0));
    for (g, &k) in set.iter().zip(&kinds) {
        let before = allocations();
        let again = evaluate(g);
        let used = allocations() - before;
        assert_eq!(again, k, "{what}: the same verdict twice");
        let slot = match k {
            Kind::ForceClosure => &mut fc,
            Kind::NoHull => &mut other,
            Kind::Boundary => &mut boundary,
        };
        slot.0 += used;
        slot.1 += 1;
    }
    let ((fc_allocations, fc), (other_allocations, other)) = (fc, other);
    eprintln!(
        "{what}: {fc_allocations} allocations for {fc} force-closure grasps ({:.1} each), \
         {other_allocations} for {other} settled without a hull, {} for {} near the boundary \
         (the exact engine on the raw wrenches)",
        fc_allocations as f64 / fc.max(1) as f64,
        boundary.0,
        boundary.1
    );
    assert!(
        fc > 5 && other > 5,
        "{what}: {fc} force closure, {other} settled without a hull"
    );
    assert_eq!(
        other_allocations, 0,
        "{what}: grasps settled by GJK allocate nothing"
    );
    assert!(
        fc_allocations <= per_grasp * fc,
        "{what}: {fc_allocations} allocations for {fc} force-closure grasps"
    );
}

#[test]
fn q1_partial_allocates_nothing_in_steady_state_but_exact_caches() {
    let mut evaluator = Evaluator::new(Metric::Q1, Method::Partial, None).unwrap();
    check_second_pass("Q1, k = 32", &grasps(32, 120), 40, |g| {
        let q = evaluator.evaluate(g).unwrap();
        kind(q.force_closure, q.stats.facets_created)
    });
}

#[test]
fn q_inf_partial_allocates_nothing_in_steady_state_but_exact_caches() {
    let metric = Metric::QInf {
        with_zero_wrench: true,
    };
    let mut evaluator = Evaluator::new(metric, Method::Partial, None).unwrap();
    check_second_pass("Q-inf with zero wrench, k = 8", &grasps(8, 60), 150, |g| {
        let q = evaluator.evaluate(g).unwrap();
        kind(q.force_closure, q.stats.facets_created)
    });
}

/// The engine itself: rebuilding hulls of generic point sets (no exact degeneracy, so no exact
/// cache) with a borrowed `ClosestToOrigin` allocates nothing once the buffers have grown.
#[test]
fn hull_rebuilds_allocate_nothing_in_steady_state() {
    use pqhull::rbox::{Family, generate};
    use pqhull::{ClosestToOrigin, Hull};
    let sets: Vec<Vec<[f64; 6]>> = (0..8)
        .map(|seed| {
            generate::<6>(&Family::SphereSurface, 150, seed)
                .into_iter()
                .map(|p| p.map(|x| x + 0.05)) // the origin off-centre
                .collect()
        })
        .collect();
    let mut strategy = ClosestToOrigin::new();
    let (mut hull, _) = Hull::try_with_strategy(&sets[0], &mut strategy).unwrap();
    for set in &sets {
        hull.rebuild_with_strategy(set, &mut strategy).unwrap();
    }
    let before = allocations();
    let mut facets = 0;
    for set in &sets {
        let result = hull.rebuild_with_strategy(set, &mut strategy).unwrap();
        facets += result.stats.facets_created;
    }
    assert!(facets > 1000, "{facets} facets: the hulls did work");
    assert_eq!(allocations() - before, 0);
}

/// Q_OWS by the partial method on a generated sphere, as above (the evaluator parks its
/// `OwsInflation` between grasps, so the force-closure ones allocate only exact caches).
#[test]
fn ows_partial_allocates_nothing_in_steady_state_but_exact_caches() {
    use pqhull::grasp::ows::ObjectWrenchSpace;
    use pqhull::mesh::{Mesh, SurfaceSampler};
    let mesh = Mesh::uv_sphere(0.3, 8, 12).unwrap();
    let friction = FrictionModel::try_new(0.5, 8).unwrap();
    let space = ObjectWrenchSpace::from_mesh(&mesh, friction).unwrap();
    let mut rng = Rng::new(4);
    let sampler = SurfaceSampler::new(&mesh);
    let set: Vec<Grasp> = (0..80)
        .map(|_| {
            let fingers = Grasp::random_on_surface(&mut rng, &sampler, 3, friction).unwrap();
            space.frame(&fingers).unwrap()
        })
        .collect();
    let mut evaluator = Evaluator::new(Metric::Ows, Method::Partial, Some(&space)).unwrap();
    check_second_pass("OWS on a sphere", &set, 100, |g| {
        let q = evaluator.evaluate(g).unwrap();
        kind(q.force_closure, q.stats.facets_created)
    });
}

/// Full builds of degenerate input in a hull's storage (`rebuild_with_strategy`): after a first
/// build has grown every buffer, one in two phases (coplanar facets kept, then the extreme
/// vertices' hull: `src/hull/coplanar.rs`) allocates no more than the strategy's own queue and
/// the first phase's examination need, whatever the number of facets or points: on the 5-D
/// cube's corners, face centres and 2,000 interior points (certified grid, so no exact cache).
#[test]
fn two_phase_full_builds_reuse_their_buffers() {
    use pqhull::rbox::{Family, generate};
    use pqhull::{FarthestPoint, Hull};
    let points = generate::<5>(&Family::CubeCornersDiamond, 2000, 1);
    let mut hull = Hull::empty();
    hull.rebuild_with_strategy(&points, FarthestPoint::new())
        .unwrap();
    let stats = hull.stats();
    assert_eq!(
        stats.points_processed - stats.expansions,
        2 * 6,
        "a second phase ran"
    );
    let rounds = 5;
    let before = allocations();
    for _ in 0..rounds {
        hull.rebuild_with_strategy(&points, FarthestPoint::new())
            .unwrap();
    }
    let per_build = (allocations() - before) / rounds;
    eprintln!(
        "two-phase 5-D build: {per_build} allocations per build ({} facets created)",
        hull.stats().facets_created
    );
    // Seen: 5 (the fresh `FarthestPoint`'s queue growing). The examination's six buffers,
    // allocated per build, would exceed the bound; an allocation per facet or per point would
    // be hundreds.
    assert!(per_build <= 8, "{per_build} allocations per build");
}
