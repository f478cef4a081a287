//! `grasp::q1_gradient` and `qinf_gradient` against central finite differences of the reported
//! value itself, on
//! seeded generic grasps (force closure and not; default and given tangents; hard and soft
//! fingers), and the non-differentiable cases flagged.

use crate::support::grasps::{Shape, random_grasp};
use pqhull::geometry::Rng;
use pqhull::grasp::quality::{Evaluator, Method, Metric};
use pqhull::grasp::{Contact, FrictionModel, Gradient, Grasp, q1_gradient, qinf_gradient};

/// The inputs of a grasp, to perturb one at a time.
#[derive(Clone)]
struct Inputs {
    positions: Vec<[f64; 3]>,
    normals: Vec<[f64; 3]>,
    tangents: Vec<Option<[f64; 3]>>,
    torsions: Vec<f64>,
    mu: f64,
    k: usize,
    reference: [f64; 3],
    rho: f64,
}

impl Inputs {
    fn grasp(&self) -> Grasp {
        let contacts = (0..self.positions.len())
            .map(|i| {
                let c = Contact::try_new(self.positions[i], self.normals[i], self.tangents[i])
                    .expect("a contact");
                c.with_torsion(self.torsions[i]).expect("a torsion")
            })
            .collect();
        Grasp::builder(contacts, FrictionModel::try_new(self.mu, self.k).unwrap())
            .torque_reference(self.reference)
            .torque_scale(self.rho)
            .build()
            .expect("a grasp")
    }
}

fn value_of(evaluator: &mut Evaluator, inputs: &Inputs) -> f64 {
    evaluator.evaluate(&inputs.grasp()).expect("Q1").value
}

/// A random grasp's inputs: contacts on an ellipsoid or a cylinder (whose normals are generic:
/// the default tangent's axis is never tied), half with given tangents, a quarter soft.
fn random_inputs(rng: &mut Rng) -> Inputs {
    let shape = if rng.uniform() < 0.5 {
        Shape::Ellipsoid
    } else {
        Shape::Cylinder
    };
    let m = 3 + rng.index(3);
    let mu = rng.uniform_in(0.2, 1.0);
    let k = [4, 6, 8][rng.index(3)];
    let grasp = random_grasp(rng, shape, m, FrictionModel::try_new(mu, k).unwrap());
    let given = rng.uniform() < 0.5;
    let soft = rng.uniform() < 0.25;
    let contacts = grasp.contacts();
    Inputs {
        positions: contacts.iter().map(|c| c.position()).collect(),
        normals: contacts.iter().map(|c| c.normal()).collect(),
        tangents: contacts
            .iter()
            .map(|_| {
                given.then(|| {
                    let u = rng.unit_vector(3);
                    [u[0], u[1], u[2]]
                })
            })
            .collect(),
        torsions: contacts
            .iter()
            .map(|_| if soft { rng.uniform_in(0.0, 0.05) } else { 0.0 })
            .collect(),
        mu,
        k,
        reference: grasp.torque_reference(),
        rho: grasp.torque_scale(),
    }
}

/// Central differences of the value (`value_of`, at `value` for `inputs`) against the analytic
/// `gradient`, every input in turn; returns (derivatives checked, kinks). At a kink within ±h
/// (another face takes over on one side, or is about to) the one-sided slopes differ, and the
/// derivative must lie between them.
fn compare_with_differences(
    what: &str,
    inputs: &Inputs,
    value: f64,
    gradient: &Gradient,
    mut value_of: impl FnMut(&Inputs) -> f64,
) -> (usize, usize) {
    let h = 1e-6;
    let mut components: Vec<(String, f64, Inputs, Inputs)> = Vec::new();
    for i in 0..inputs.positions.len() {
        for a in 0..3 {
            let (mut plus, mut minus) = (inputs.clone(), inputs.clone());
            plus.positions[i][a] += h;
            minus.positions[i][a] -= h;
            components.push((format!("p{i}[{a}]"), gradient.positions[i][a], plus, minus));
            // Along the sphere: n ± h·(e_a − n_a n), normalised by the contact.
            let n = inputs.normals[i];
            let d: [f64; 3] = std::array::from_fn(|c| f64::from(c == a) - n[a] * n[c]);
            let (mut plus, mut minus) = (inputs.clone(), inputs.clone());
            plus.normals[i] = std::array::from_fn(|c| n[c] + h * d[c]);
            minus.normals[i] = std::array::from_fn(|c| n[c] - h * d[c]);
            components.push((format!("n{i}[{a}]"), gradient.normals[i][a], plus, minus));
        }
    }
    let (mut plus, mut minus) = (inputs.clone(), inputs.clone());
    plus.mu += h;
    minus.mu -= h;
    components.push(("mu".to_string(), gradient.friction, plus, minus));
    let (mut checked, mut kinks) = (0, 0);
    for (name, analytic, plus, minus) in components {
        let (up, down) = (value_of(&plus), value_of(&minus));
        let central = (up - down) / (2.0 * h);
        let (forward, backward) = ((up - value) / h, (value - down) / h);
        let scale = 1.0 + analytic.abs();
        if (central - analytic).abs() <= 1e-5 * scale {
            checked += 1;
            continue;
        }
        let (low, high) = (forward.min(backward), forward.max(backward));
        assert!(
            high - low > 2e-5 * scale
                && analytic >= low - 1e-5 * scale
                && analytic <= high + 1e-5 * scale,
            "{what} (value {value}), ∂/∂{name}: analytic {analytic}, central difference \
             {central} (one-sided {forward}, {backward})"
        );
        kinks += 1;
    }
    (checked, kinks)
}

/// [`compare_with_differences`] for `metric` on `count` differentiable random grasps; returns
/// (grasps, force closure, derivatives checked, kinks, flagged, flagged force closure).
fn check_against_differences(
    metric: Metric,
    count: usize,
    seed: u64,
    gradient_of: impl Fn(&Grasp, &pqhull::grasp::quality::Quality) -> Gradient,
) -> (usize, usize, usize, usize, usize, usize) {
    let mut rng = Rng::new(seed);
    let mut evaluator = Evaluator::new(metric, Method::Partial);
    let (mut grasps, mut inside, mut flagged, mut checked, mut kinks) = (0, 0, 0, 0, 0);
    let mut flagged_inside = 0;
    while grasps < count {
        let inputs = random_inputs(&mut rng);
        let grasp = inputs.grasp();
        let quality = evaluator.evaluate(&grasp).unwrap();
        let gradient = gradient_of(&grasp, &quality);
        if !gradient.differentiable {
            flagged += 1;
            flagged_inside += usize::from(quality.force_closure);
            continue;
        }
        grasps += 1;
        inside += usize::from(quality.force_closure);
        let what = format!("{metric:?}, grasp {grasps}");
        let (c, k) = compare_with_differences(&what, &inputs, quality.value, &gradient, |i| {
            value_of(&mut evaluator, i)
        });
        checked += c;
        kinks += k;
    }
    eprintln!(
        "{metric:?}: {grasps} grasps ({inside} force closure), {checked} derivatives checked, \
         {kinks} at a kink, {flagged} grasps flagged non-differentiable ({flagged_inside} of \
         them force closure)"
    );
    assert!(
        kinks * 50 <= checked,
        "{kinks} kinks for {checked} derivatives"
    );
    (grasps, inside, checked, kinks, flagged, flagged_inside)
}

#[test]
fn q1_gradient_is_the_finite_difference_of_q1() {
    let (grasps, inside, ..) =
        check_against_differences(Metric::Q1, 300, 2812, |g, q| q1_gradient(g, q).unwrap());
    assert!(
        inside >= 30 && grasps - inside >= 30,
        "both kinds: {inside} of {grasps}"
    );
}

#[test]
fn qinf_gradient_is_the_finite_difference_of_qinf() {
    // Q∞ is rarely force closure on these grasps: more of them.
    let plain = Metric::QInf {
        with_zero_wrench: false,
    };
    let (grasps, inside, ..) =
        check_against_differences(plain, 150, 2813, |g, q| qinf_gradient(g, q, false).unwrap());
    assert!(
        inside >= 8 && grasps - inside >= 30,
        "both kinds: {inside} of {grasps}"
    );
    // With the zero wrench the sum holds the origin: a grasp that is not force closure has
    // Q∞ = 0 on the boundary, flagged; the others are all force closure.
    let zero = Metric::QInf {
        with_zero_wrench: true,
    };
    let (grasps, inside, .., flagged_inside) =
        check_against_differences(zero, 20, 2814, |g, q| qinf_gradient(g, q, true).unwrap());
    assert_eq!(inside, grasps);
    // Generic force-closure grasps are differentiable: a face of the sum with a pyramid's whole
    // rim on it (k points, 2-dimensional with the zero wrench beside it) is not a tie.
    assert!(
        flagged_inside * 10 <= grasps,
        "{flagged_inside} force-closure grasps flagged, {grasps} not"
    );
}

/// Where Q1 is not differentiable the gradient says so: a box's axis-aligned normals (the
/// default tangent's axis tied), the origin on the boundary (two opposite contacts without
/// friction), and repeated contacts.
#[test]
fn non_differentiable_grasps_are_flagged() {
    let mut evaluator = Evaluator::new(Metric::Q1, Method::Partial);
    let flagged = |evaluator: &mut Evaluator, grasp: &Grasp| {
        let quality = evaluator.evaluate(grasp).unwrap();
        !q1_gradient(grasp, &quality).unwrap().differentiable
    };
    let contact = |p: [f64; 3], n: [f64; 3]| Contact::try_new(p, n, None).unwrap();
    let friction = FrictionModel::try_new(0.5, 8).unwrap();
    // A box: normals ±e_x, ±e_y, ±e_z.
    let boxed = Grasp::builder(
        vec![
            contact([1.0, 0.2, 0.1], [-1.0, 0.0, 0.0]),
            contact([-1.0, -0.1, 0.3], [1.0, 0.0, 0.0]),
            contact([0.3, 1.0, -0.2], [0.0, -1.0, 0.0]),
            contact([0.1, 0.2, -1.0], [0.0, 0.0, 1.0]),
        ],
        friction,
    )
    .build()
    .unwrap();
    assert!(flagged(&mut evaluator, &boxed));
    // Two opposite contacts: never force closure, the origin on the hull's boundary.
    let pinch = Grasp::builder(
        vec![
            contact([1.0, 0.0, 0.0], [-1.0, 0.3, 0.2]),
            contact([-1.0, 0.0, 0.0], [1.0, -0.3, -0.2]),
        ],
        friction,
    )
    .build()
    .unwrap();
    assert!(flagged(&mut evaluator, &pinch));
    // A generic grasp is differentiable; listing one of its contacts twice is a tie.
    let mut rng = Rng::new(5);
    let generic = loop {
        let inputs = random_inputs(&mut rng);
        let grasp = inputs.grasp();
        if !flagged(&mut evaluator, &grasp) {
            break grasp;
        }
    };
    let mut twice = generic.contacts().to_vec();
    twice.extend_from_slice(generic.contacts());
    let repeated = Grasp::builder(twice, generic.friction())
        .torque_reference(generic.torque_reference())
        .torque_scale(generic.torque_scale())
        .build()
        .unwrap();
    assert!(flagged(&mut evaluator, &repeated));
}

/// Q_OWS against central differences of Q_OWS, on force-closure grasps and random task wrench
/// spaces of 12 disturbances.
#[test]
fn ows_gradient_is_the_finite_difference_of_ows() {
    use crate::support::grasps::random_disturbances;
    use pqhull::grasp::ows::{ObjectWrenchSpace, OwsEvaluator};
    let mut rng = Rng::new(2815);
    let mut evaluator = OwsEvaluator::new(Method::Partial);
    let (mut grasps, mut flagged, mut checked, mut kinks) = (0, 0, 0, 0);
    while grasps < 60 {
        let inputs = random_inputs(&mut rng);
        let space =
            ObjectWrenchSpace::from_disturbances(random_disturbances(&mut rng, 12)).unwrap();
        let grasp = inputs.grasp();
        let quality = evaluator.evaluate(&grasp, &space).unwrap();
        let Some(value) = quality.value else { continue };
        let gradient = pqhull::grasp::ows_gradient(&grasp, &space, &quality).unwrap();
        if !gradient.differentiable {
            flagged += 1;
            continue;
        }
        grasps += 1;
        let what = format!("Q_OWS, grasp {grasps}");
        let (c, k) = compare_with_differences(&what, &inputs, value, &gradient, |i| {
            let q = evaluator.evaluate(&i.grasp(), &space).unwrap();
            q.value.expect("still force closure")
        });
        checked += c;
        kinks += k;
    }
    eprintln!(
        "Q_OWS: {grasps} grasps, {checked} derivatives checked, {kinks} at a kink, {flagged} \
         flagged non-differentiable"
    );
    assert!(
        kinks * 50 <= checked,
        "{kinks} kinks for {checked} derivatives"
    );
}
