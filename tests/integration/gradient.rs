//! `grasp::q1_gradient` and `qinf_gradient` against central finite differences of the reported
//! value itself, on
//! seeded generic grasps (force closure and not; default and given tangents; hard and soft
//! fingers), and the non-differentiable cases flagged.

use crate::support::grasps::{Shape, random_grasp};
use pqhull::geometry::Rng;
use pqhull::grasp::{
    Contact, Evaluation, Evaluator, FrictionModel, Gradient, Grasp, Method, Metric, q1_gradient,
    qinf_gradient,
};

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
    let evaluation = evaluator.evaluate(&inputs.grasp()).expect("Q1");
    evaluation.value.expect("Q1 and Q∞ have a value")
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
    gradient_of: impl Fn(&Grasp, &Evaluation) -> Gradient,
) -> (usize, usize, usize, usize, usize, usize) {
    let mut rng = Rng::new(seed);
    let mut evaluator = Evaluator::new(metric, Method::Partial, None).unwrap();
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
        let value = quality.value.expect("Q1 and Q∞ have a value");
        let (c, k) = compare_with_differences(&what, &inputs, value, &gradient, |i| {
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
        check_against_differences(plain, 150, 2813, |g, q| qinf_gradient(g, q).unwrap());
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
        check_against_differences(zero, 20, 2814, |g, q| qinf_gradient(g, q).unwrap());
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
    let mut evaluator = Evaluator::new(Metric::Q1, Method::Partial, None).unwrap();
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

/// A grasp symmetric under the mirror x → −x (positions, normals and given tangents mirrored,
/// the torque reference on the mirror plane) maps its wrench hull onto itself, each wrench
/// (f, τ) to (−fx, fy, fz, τx, −τy, −τz): unless the nearest facet is its own mirror image, it
/// and its image are equally near, and Q1 (Q∞ likewise) is the minimum of the two there, not
/// differentiable. Every such grasp among random mirror-symmetric ones is flagged, by the
/// partial and the full method; moving one contact by 1e−3 (breaking the symmetry) unflags it.
#[test]
fn ties_between_mirrored_facets_are_flagged() {
    let unit = |v: [f64; 3]| {
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        v.map(|c| c / l)
    };
    let mirror = |v: [f64; 3]| [-v[0], v[1], v[2]];
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let mirror_wrench = |w: &[f64; 6]| [-w[0], w[1], w[2], w[3], -w[4], -w[5]];
    let mut rng = Rng::new(41);
    use crate::support::grasps::random_disturbances;
    use pqhull::grasp::ows::ObjectWrenchSpace;
    let (mut tied, mut own_image, mut ows_tied) = (0, 0, 0);
    for _ in 0..60 {
        // Two contacts on the unit sphere (normals inward, a tangent given) and their mirrors.
        let sites: Vec<[f64; 3]> = (0..2)
            .map(|_| unit([rng.normal(), rng.normal(), rng.normal()]))
            .collect();
        let grasp_of = |nudge: f64| {
            let mut contacts = Vec::new();
            for &p in &sites {
                let n = p.map(|c| -c);
                let t = unit(cross(n, [0.3, 0.5, 0.8]));
                contacts.push(Contact::try_new(p, n, Some(t)).unwrap());
                let q = [mirror(p)[0] + nudge, p[1], p[2]];
                contacts.push(Contact::try_new(q, mirror(n), Some(mirror(t))).unwrap());
            }
            Grasp::builder(contacts, FrictionModel::try_new(0.8, 8).unwrap())
                .torque_reference([0.0; 3])
                .torque_scale(1.0)
                .build()
                .unwrap()
        };
        let (symmetric, broken) = (grasp_of(0.0), grasp_of(1e-3));
        let mut partial = Evaluator::new(Metric::Q1, Method::Partial, None).unwrap();
        let quality = partial.evaluate(&symmetric).unwrap();
        if !quality.force_closure {
            continue;
        }
        if is_self_mirrored(&quality, mirror_wrench) {
            own_image += 1;
            continue;
        }
        tied += 1;
        let mut full = Evaluator::new(Metric::Q1, Method::Full, None).unwrap();
        for (method, evaluator) in [("partial", &mut partial), ("full", &mut full)] {
            let quality = evaluator.evaluate(&symmetric).unwrap();
            assert!(quality.tied(), "{method}: {quality:?}");
            assert!(!q1_gradient(&symmetric, &quality).unwrap().differentiable);
            let quality = evaluator.evaluate(&broken).unwrap();
            assert!(!quality.tied(), "{method}, symmetry broken: {quality:?}");
        }
        let qinf = Metric::QInf {
            with_zero_wrench: true,
        };
        let quality = Evaluator::new(qinf, Method::Partial, None)
            .unwrap()
            .evaluate(&symmetric)
            .unwrap();
        if quality.force_closure {
            assert!(quality.tied() || is_self_mirrored(&quality, mirror_wrench));
        }
        // Q_OWS against a mirror-symmetric set of disturbances: the deciding disturbance's
        // image leaves through the image of its facet as early. Through the same facet when
        // that is its own image (flagged by the disturbances' tie), else through another
        // (`tied`): never differentiable, by either exact method.
        let half = random_disturbances(&mut rng, 6);
        let both: Vec<[f64; 6]> = half.iter().flat_map(|d| [*d, mirror_wrench(d)]).collect();
        let space = ObjectWrenchSpace::from_disturbances(both).unwrap();
        for method in [Method::Partial, Method::Full] {
            let mut evaluator = Evaluator::new(Metric::Ows, method, Some(&space)).unwrap();
            let quality = evaluator.evaluate(&symmetric).unwrap();
            if quality.value.is_none() {
                continue;
            }
            ows_tied += usize::from(quality.tied());
            let gradient = pqhull::grasp::ows_gradient(&symmetric, &space, &quality).unwrap();
            assert!(!gradient.differentiable, "{method:?}: {quality:?}");
            let moved = evaluator.evaluate(&broken).unwrap();
            assert!(!moved.tied(), "{method:?}, symmetry broken: {moved:?}");
        }
    }
    eprintln!(
        "{tied} mirrored ties flagged, {own_image} nearest facets their own image; Q_OWS: \
         {ows_tied} ties through another facet"
    );
    assert!(tied >= 5, "only {tied} ties among the force-closure grasps");
    assert!(
        ows_tied >= 5,
        "only {ows_tied} Q_OWS ties through another facet"
    );
}

/// Whether the plane of the deciding wrenches of `quality` is its own image under `mirror`
/// (a linear isometry): its unit normal, by Gram–Schmidt on the simplex's edges, is fixed.
fn is_self_mirrored(quality: &Evaluation, mirror: impl Fn(&[f64; 6]) -> [f64; 6]) -> bool {
    let (u, _) = crate::support::simplex_normal(quality.deciding_wrenches());
    let image = mirror(&u);
    let apart = |s: f64| {
        (0..6)
            .map(|c| (image[c] - s * u[c]).powi(2))
            .sum::<f64>()
            .sqrt()
    };
    apart(1.0) < 1e-6 || apart(-1.0) < 1e-6
}

/// Q_OWS against central differences of Q_OWS, on force-closure grasps and random task wrench
/// spaces of 12 disturbances.
#[test]
fn ows_gradient_is_the_finite_difference_of_ows() {
    use crate::support::grasps::random_disturbances;
    use pqhull::grasp::ows::ObjectWrenchSpace;
    let mut rng = Rng::new(2815);
    let (mut grasps, mut flagged, mut checked, mut kinks) = (0, 0, 0, 0);
    while grasps < 60 {
        let inputs = random_inputs(&mut rng);
        let space =
            ObjectWrenchSpace::from_disturbances(random_disturbances(&mut rng, 12)).unwrap();
        let grasp = inputs.grasp();
        let mut evaluator = Evaluator::new(Metric::Ows, Method::Partial, Some(&space)).unwrap();
        let quality = evaluator.evaluate(&grasp).unwrap();
        let Some(value) = quality.value else { continue };
        let gradient = pqhull::grasp::ows_gradient(&grasp, &space, &quality).unwrap();
        if !gradient.differentiable {
            flagged += 1;
            continue;
        }
        grasps += 1;
        let what = format!("Q_OWS, grasp {grasps}");
        let (c, k) = compare_with_differences(&what, &inputs, value, &gradient, |i| {
            let q = evaluator.evaluate(&i.grasp()).unwrap();
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
