//! The benchmarks' inputs: seeded grasp sets and point sets, the same for every run with the
//! same seed, so that rows of different runs (and methods within a run) measure the same work.

use pqhull::geometry::Rng;
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::grasp::{FrictionModel, Grasp, GraspError};
use pqhull::mesh::{Mesh, SurfaceSampler};
use pqhull::rbox::{Family, generate};

/// Half extents of the GWS benchmark's object: a 1 × 0.4 × 0.2 bar.
pub const BAR_HALF_EXTENTS: [f64; 3] = [0.5, 0.2, 0.1];

/// Friction coefficient of the GWS benchmark's grasps.
pub const BAR_FRICTION: f64 = 0.5;

/// `count` random grasps of `contacts` fingers on the GWS benchmark's bar
/// ([`BAR_HALF_EXTENTS`], [`Grasp::random_on_box`]), all from one generator seeded with `seed`.
///
/// ```
/// use pqhull_cli::bench::workloads::{BAR_FRICTION, bar_grasps};
/// use pqhull::grasp::FrictionModel;
/// let friction = FrictionModel::try_new(BAR_FRICTION, 8)?;
/// let grasps = bar_grasps(1, 3, 4, friction);
/// assert_eq!(grasps.len(), 3);
/// assert_eq!(grasps, bar_grasps(1, 3, 4, friction)); // seeded: the same every time
/// # Ok::<(), pqhull::grasp::GraspError>(())
/// ```
///
/// # Panics
/// If `contacts` is 0 (as [`Grasp::random_on_box`]).
pub fn bar_grasps(seed: u64, count: usize, contacts: usize, friction: FrictionModel) -> Vec<Grasp> {
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|_| Grasp::random_on_box(&mut rng, BAR_HALF_EXTENTS, contacts, friction))
        .collect()
}

/// The object of the GWS benchmark's grasps.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GwsObject {
    /// The 1 × 0.4 × 0.2 bar ([`BAR_HALF_EXTENTS`], [`Grasp::random_on_box`]): axis-aligned
    /// normals, so contacts on one face share their friction pyramid's orientation.
    #[default]
    Bar,
    /// The ellipsoid with the bar's half extents as semi-axes ([`Grasp::random_on_ellipsoid`]):
    /// every normal different.
    Ellipsoid,
}

impl GwsObject {
    /// The name `pqh bench gws --object` takes.
    pub fn name(self) -> &'static str {
        match self {
            GwsObject::Bar => "bar",
            GwsObject::Ellipsoid => "ellipsoid",
        }
    }
}

/// `count` random grasps of `contacts` fingers on `object`, all from one generator seeded with
/// `seed` ([`bar_grasps`] for the bar).
///
/// ```
/// use pqhull_cli::bench::workloads::{BAR_FRICTION, GwsObject, bar_grasps, object_grasps};
/// use pqhull::grasp::FrictionModel;
/// let friction = FrictionModel::try_new(BAR_FRICTION, 8)?;
/// assert_eq!(object_grasps(GwsObject::Bar, 1, 3, 4, friction), bar_grasps(1, 3, 4, friction));
/// let round = object_grasps(GwsObject::Ellipsoid, 1, 3, 4, friction);
/// assert_eq!(round.len(), 3);
/// assert_ne!(round, bar_grasps(1, 3, 4, friction));
/// # Ok::<(), pqhull::grasp::GraspError>(())
/// ```
///
/// # Panics
/// If `contacts` is 0.
pub fn object_grasps(
    object: GwsObject,
    seed: u64,
    count: usize,
    contacts: usize,
    friction: FrictionModel,
) -> Vec<Grasp> {
    match object {
        GwsObject::Bar => bar_grasps(seed, count, contacts, friction),
        GwsObject::Ellipsoid => {
            let mut rng = Rng::new(seed);
            (0..count)
                .map(|_| Grasp::random_on_ellipsoid(&mut rng, BAR_HALF_EXTENTS, contacts, friction))
                .collect()
        }
    }
}

/// `count` random grasps of `contacts` fingers at area-uniform points of `mesh`'s surface
/// ([`Grasp::random_on_surface`]), each put in `space`'s torque frame
/// ([`ObjectWrenchSpace::frame`]); one generator seeded with `seed`.
///
/// # Errors
/// [`GraspError`] when `contacts` is 0, or a grasp cannot be put in the space's frame.
pub fn surface_grasps(
    mesh: &Mesh,
    space: &ObjectWrenchSpace,
    seed: u64,
    count: usize,
    contacts: usize,
    friction: FrictionModel,
) -> Result<Vec<Grasp>, GraspError> {
    let mut rng = Rng::new(seed);
    let sampler = SurfaceSampler::new(mesh);
    (0..count)
        .map(|_| {
            let grasp = Grasp::random_on_surface(&mut rng, &sampler, contacts, friction)?;
            space.frame(&grasp)
        })
        .collect()
}

/// One named point set of the full-vs-partial comparison.
#[derive(Clone, Debug, PartialEq)]
pub struct PointSet<const D: usize> {
    /// A short name: `sphere`, `cube` or `wrenches`.
    pub name: &'static str,
    /// One line saying what the points are.
    pub description: String,
    /// The points.
    pub points: Vec<[f64; D]>,
}

/// The comparison's point sets in dimension `D`: `n` points on the sphere of radius 0.5 (every
/// point a hull vertex: the hardest case) and `n` uniform in [−0.5, 0.5)^D.
///
/// ```
/// use pqhull_cli::bench::workloads::point_sets;
/// let sets = point_sets::<4>(100, 1);
/// assert_eq!(sets.iter().map(|s| s.name).collect::<Vec<_>>(), ["sphere", "cube"]);
/// assert!(sets.iter().all(|s| s.points.len() == 100));
/// ```
pub fn point_sets<const D: usize>(n: usize, seed: u64) -> Vec<PointSet<D>> {
    vec![
        PointSet {
            name: "sphere",
            description: format!("{n} points on the {D}-D sphere of radius 0.5 (all extreme)"),
            points: generate::<D>(&Family::SphereSurface, n, seed),
        },
        PointSet {
            name: "cube",
            description: format!("{n} points uniform in [-0.5, 0.5)^{D}"),
            points: generate::<D>(&Family::UniformCube, n, seed),
        },
    ]
}

/// The comparison's 6-D set: the 32 wrenches of a grasp-like random grasp, 4 contacts on
/// distinct faces of the unit box [−0.5, 0.5]³ (centred on the torque reference) with 8
/// friction-cone edges each, μ = 0.5 ([`Grasp::random_on_distinct_faces`],
/// [`Grasp::wrenches`]).
///
/// ```
/// use pqhull_cli::bench::workloads::wrench_set;
/// let set = wrench_set(7);
/// assert_eq!((set.name, set.points.len()), ("wrenches", 32));
/// ```
pub fn wrench_set(seed: u64) -> PointSet<6> {
    const CONTACTS: usize = 4;
    const EDGES: usize = 8;
    const MU: f64 = 0.5;
    let friction = FrictionModel::try_new(MU, EDGES).expect("a valid friction model");
    let grasp = Grasp::random_on_distinct_faces(&mut Rng::new(seed), [0.5; 3], CONTACTS, friction);
    PointSet {
        name: "wrenches",
        description: "32 grasp-like wrenches: 4 contacts x 8 friction-cone edges, mu = 0.5"
            .to_string(),
        points: grasp.wrenches(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_wrench_set_is_the_documented_formula() {
        // The generator `pqh compare` used before the grasp layer existed, kept as the reference:
        // the set must not change under the seeds people have reported.
        fn reference(seed: u64) -> Vec<[f64; 6]> {
            use pqhull::geometry::vector::cross;
            let mut rng = Rng::new(seed);
            let mut faces: [usize; 6] = [0, 1, 2, 3, 4, 5];
            for i in 0..4 {
                let j = i + rng.index(6 - i);
                faces.swap(i, j);
            }
            let mut out = Vec::new();
            for &face in &faces[..4] {
                let (axis, sign) = (face / 2, if face % 2 == 0 { -1.0 } else { 1.0 });
                let mut p = [0.0; 3];
                for (c, x) in p.iter_mut().enumerate() {
                    *x = if c == axis {
                        0.5 * sign
                    } else {
                        rng.uniform_in(-0.5, 0.5)
                    };
                }
                let mut n = [0.0; 3];
                n[axis] = -sign;
                let mut t = [0.0; 3];
                t[(axis + 1) % 3] = 1.0;
                let b = cross(n, t);
                for j in 0..8 {
                    let theta = std::f64::consts::TAU * j as f64 / 8.0;
                    let f: [f64; 3] = std::array::from_fn(|c| {
                        n[c] + 0.5 * (theta.cos() * t[c] + theta.sin() * b[c])
                    });
                    let torque = cross(p, f);
                    out.push([f[0], f[1], f[2], torque[0], torque[1], torque[2]]);
                }
            }
            out
        }
        for seed in [1, 20240601, 0xdead_beef] {
            let bits = |set: &[[f64; 6]]| -> Vec<[u64; 6]> {
                set.iter().map(|w| w.map(f64::to_bits)).collect()
            };
            assert_eq!(
                bits(&wrench_set(seed).points),
                bits(&reference(seed)),
                "seed {seed}"
            );
        }
    }

    #[test]
    fn surface_grasps_are_in_the_space_frame() {
        let mesh = Mesh::cuboid([0.5, 0.3, 0.2]).unwrap();
        let friction = FrictionModel::try_new(0.5, 4).unwrap();
        let space = ObjectWrenchSpace::from_mesh(&mesh, friction).unwrap();
        let grasps = surface_grasps(&mesh, &space, 3, 5, 3, friction).unwrap();
        assert_eq!(grasps.len(), 5);
        let (c, rho) = space.torque_frame().unwrap();
        assert!(
            grasps
                .iter()
                .all(|g| g.torque_reference() == c && g.torque_scale() == rho)
        );
        assert!(surface_grasps(&mesh, &space, 3, 1, 0, friction).is_err());
    }
}
