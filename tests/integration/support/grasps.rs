//! The tests' seeded grasps, the one generator every test takes them from: on the seed paper's
//! bar (the library's [`Grasp::random_on_box`]) and on a box, an ellipsoid or a cylinder with
//! random extents, tangents and torque frames; random disturbances; a grasp varied by one
//! parameter.

use pqhull::geometry::Rng;
use pqhull::grasp::{Contact, FrictionModel, Grasp};
use std::f64::consts::PI;

/// Half extents of the seed paper's 1 × 0.4 × 0.2 bar.
pub const BAR_HALF_EXTENTS: [f64; 3] = [0.5, 0.2, 0.1];

/// Friction coefficient of the bar grasps ([`bar_grasps`]).
pub const BAR_FRICTION: f64 = 0.5;

/// `count` seeded random grasps of `contacts` fingers on the seed paper's 1 × 0.4 × 0.2 bar,
/// by the library's generator ([`Grasp::random_on_box`](Grasp::random_on_box)).
pub fn bar_grasps(seed: u64, count: usize, contacts: usize, friction: FrictionModel) -> Vec<Grasp> {
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|_| Grasp::random_on_box(&mut rng, BAR_HALF_EXTENTS, contacts, friction))
        .collect()
}

/// A grasp of `m` contacts on the bar with a random friction coefficient in [0.2, 1] and `k`
/// cone edges.
pub fn random_bar_grasp(rng: &mut Rng, m: usize, k: usize) -> Grasp {
    let mu = rng.uniform_in(0.2, 1.0);
    Grasp::random_on_box(
        rng,
        BAR_HALF_EXTENTS,
        m,
        FrictionModel::try_new(mu, k).unwrap(),
    )
}

#[derive(Clone, Copy, Debug)]
pub enum Shape {
    Ellipsoid,
    Box,
    Cylinder,
}

impl Shape {
    pub const ALL: [Shape; 3] = [Shape::Ellipsoid, Shape::Box, Shape::Cylinder];

    pub fn name(self) -> &'static str {
        match self {
            Shape::Ellipsoid => "ellipsoid",
            Shape::Box => "box",
            Shape::Cylinder => "cylinder",
        }
    }
}

/// A random unit vector of R³.
pub fn unit3(rng: &mut Rng) -> [f64; 3] {
    let v = rng.unit_vector(3);
    [v[0], v[1], v[2]]
}

/// A contact with a random given tangent half the time (the default tangent otherwise).
fn contact(rng: &mut Rng, p: [f64; 3], n: [f64; 3]) -> Contact {
    let tangent = (rng.uniform() < 0.5).then(|| unit3(rng));
    Contact::try_new(p, n, tangent)
        .or_else(|_| Contact::try_new(p, n, None))
        .expect("a valid contact")
}

/// A contact on the surface of `shape` (extents `size`) with its inward normal.
fn surface_contact(rng: &mut Rng, shape: Shape, size: [f64; 3]) -> Contact {
    match shape {
        Shape::Ellipsoid => {
            let u = unit3(rng);
            let p: [f64; 3] = std::array::from_fn(|a| size[a] * u[a]);
            let n: [f64; 3] = std::array::from_fn(|a| -p[a] / (size[a] * size[a]));
            contact(rng, p, n)
        }
        Shape::Box => {
            let axis = rng.index(3);
            let sign = if rng.uniform() < 0.5 { -1.0 } else { 1.0 };
            let mut p: [f64; 3] = std::array::from_fn(|a| rng.uniform_in(-size[a], size[a]));
            p[axis] = sign * size[axis];
            let mut n = [0.0; 3];
            n[axis] = -sign;
            contact(rng, p, n)
        }
        Shape::Cylinder => {
            // size = [radius, radius, half height]; side or caps by area.
            let (r, h) = (size[0], size[2]);
            let side = 4.0 * PI * r * h;
            let caps = 2.0 * PI * r * r;
            let phi = rng.uniform_in(0.0, 2.0 * PI);
            if rng.uniform() * (side + caps) < side {
                let p = [r * phi.cos(), r * phi.sin(), rng.uniform_in(-h, h)];
                contact(rng, p, [-phi.cos(), -phi.sin(), 0.0])
            } else {
                let rad = r * rng.uniform().sqrt();
                let sign = if rng.uniform() < 0.5 { -1.0 } else { 1.0 };
                let p = [rad * phi.cos(), rad * phi.sin(), sign * h];
                contact(rng, p, [0.0, 0.0, -sign])
            }
        }
    }
}

/// Random extents of `shape`.
pub fn random_size(rng: &mut Rng, shape: Shape) -> [f64; 3] {
    match shape {
        Shape::Cylinder => {
            let r = rng.uniform_in(0.02, 0.5);
            [r, r, rng.uniform_in(0.05, 0.5)]
        }
        _ => std::array::from_fn(|_| rng.uniform_in(0.05, 0.6)),
    }
}

/// A torque frame for an object of extents `size`: half the time the default (origin, ρ = 1 for
/// the box through `Grasp::random_on_box`'s half-diagonal), otherwise a reference point near the
/// centre and ρ the largest distance from it to the bounding box.
fn frame(rng: &mut Rng, size: [f64; 3]) -> ([f64; 3], f64) {
    let half_diagonal = size.iter().map(|h| h * h).sum::<f64>().sqrt();
    if rng.uniform() < 0.5 {
        return ([0.0; 3], half_diagonal);
    }
    let c: [f64; 3] = std::array::from_fn(|a| rng.uniform_in(-0.2, 0.2) * size[a]);
    let rho = (0..3)
        .map(|a| (size[a] + c[a].abs()).powi(2))
        .sum::<f64>()
        .sqrt();
    (c, rho)
}

/// A seeded grasp: `m` contacts on `shape`, μ and k given.
pub fn random_grasp(rng: &mut Rng, shape: Shape, m: usize, friction: FrictionModel) -> Grasp {
    let size = random_size(rng, shape);
    if let Shape::Box = shape
        && rng.uniform() < 0.5
    {
        // The crate's own generator (default tangents, centre reference, half-diagonal scale).
        return Grasp::random_on_box(rng, size, m, friction);
    }
    let contacts = (0..m).map(|_| surface_contact(rng, shape, size)).collect();
    let (c, rho) = frame(rng, size);
    Grasp::builder(contacts, friction)
        .torque_reference(c)
        .torque_scale(rho)
        .build()
        .expect("a valid grasp")
}

/// `m` random 6-D disturbances (random directions, lengths in [0.2, 1]).
pub fn random_disturbances(rng: &mut Rng, count: usize) -> Vec<[f64; 6]> {
    (0..count)
        .map(|_| {
            let u = rng.unit_vector(6);
            let length = rng.uniform_in(0.2, 1.0);
            std::array::from_fn(|c| u[c] * length)
        })
        .collect()
}

/// The same grasp with another friction coefficient.
pub fn with_friction(grasp: &Grasp, mu: f64) -> Grasp {
    let fm = FrictionModel::try_new(mu, grasp.friction().cone_edges()).expect("μ ≥ 0");
    with_friction_model(grasp, fm)
}

/// The same grasp with another friction model.
pub fn with_friction_model(grasp: &Grasp, friction: FrictionModel) -> Grasp {
    Grasp::builder(grasp.contacts().to_vec(), friction)
        .torque_reference(grasp.torque_reference())
        .torque_scale(grasp.torque_scale())
        .build()
        .expect("a valid grasp")
}

/// The same grasp with contact `i` moved to `p + s·v` (same normal and tangent).
pub fn with_contact_moved(grasp: &Grasp, i: usize, v: [f64; 3], s: f64) -> Grasp {
    let mut contacts = grasp.contacts().to_vec();
    let c = contacts[i];
    let p = c.position();
    let moved = [p[0] + s * v[0], p[1] + s * v[1], p[2] + s * v[2]];
    contacts[i] = Contact::try_new(moved, c.normal(), Some(c.tangent())).expect("valid");
    Grasp::builder(contacts, grasp.friction())
        .torque_reference(grasp.torque_reference())
        .torque_scale(grasp.torque_scale())
        .build()
        .expect("a valid grasp")
}

/// Every sum of one point from each of `sets`, the first set's choice slowest: a Minkowski sum
/// written out in the test, no merging (`Σ_i w_i(j_i)`, summed in set order).
pub fn sum_of_sets(sets: &[Vec<[f64; 6]>]) -> Vec<[f64; 6]> {
    let mut sums = vec![[0.0; 6]];
    for set in sets {
        sums = sums
            .iter()
            .flat_map(|s| {
                set.iter()
                    .map(move |w| std::array::from_fn(|c| s[c] + w[c]))
            })
            .collect();
    }
    sums
}

/// The materialised Minkowski sum of `grasp`'s contact wrench sets
/// ([`Grasp::contact_wrenches`]), each with the zero wrench when `with_zero_wrench`: the points
/// the Q∞ metrics hull, in contact order.
pub fn minkowski_points(grasp: &Grasp, with_zero_wrench: bool) -> Vec<[f64; 6]> {
    let sets: Vec<Vec<[f64; 6]>> = (0..grasp.contact_count())
        .map(|i| {
            let mut set = vec![[0.0; 6]; grasp.contact_wrench_count(i)];
            grasp.contact_wrenches(i, &mut set);
            if with_zero_wrench {
                set.push([0.0; 6]);
            }
            set
        })
        .collect();
    sum_of_sets(&sets)
}
