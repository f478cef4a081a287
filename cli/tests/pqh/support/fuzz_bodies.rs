//! The bodies of the fuzz targets, shared by `fuzz/fuzz_targets/*.rs` (cargo-fuzz, nightly) and
//! `tests/fuzz_bounded.rs` (bounded replay on stable), so that both run the very same code.
//!
//! Each body takes the raw input bytes and returns normally unless it finds a bug: a panic in
//! the library, or a result that breaks a documented promise (an invalid hull by
//! [`Hull::check`], a parsed value that is not what was written, …), which it turns into a panic
//! with a message. An `Err` from the library is a fine answer to malformed input.
//!
//! Only `pqhull` and `std` are used here: the fuzz crate and the integration tests both have them.
#![allow(dead_code)]

use pqhull::grasp::json::{parse_grasp, split_grasps};
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::grasp::{
    Evaluation, Evaluator, FrictionModel, Grasp, MAX_CONE_EDGES, MAX_CONTACTS, MIN_CONE_EDGES,
    Method, Metric, QualityError,
};
use pqhull::mesh::Mesh;
use pqhull::predicates::Sign;
use pqhull::{ClosestToOrigin, FarthestPoint, Hull, HullError};
use pqhull_cli::points_file::parse_points;

/// The fuzz targets, by name: the name of the target, of its `fuzz/regressions/` directory and
/// of the body below.
pub const TARGETS: [&str; 5] = [
    "points_file",
    "grasp_json",
    "mesh_obj",
    "mesh_stl",
    "engine",
];

/// Runs target `name` on `data`.
///
/// # Panics
/// On a bug (see the module docs), or for an unknown name.
pub fn run(name: &str, data: &[u8]) {
    match name {
        "points_file" => points_file(data),
        "grasp_json" => grasp_json(data),
        "mesh_obj" => mesh_obj(data),
        "mesh_stl" => mesh_stl(data),
        "engine" => engine(data),
        _ => panic!("no fuzz target named {name}"),
    }
}

/// Text for the text formats: invalid UTF-8 is replaced (U+FFFD), as a lossy reader would, so
/// that every input reaches the parser.
fn text(data: &[u8]) -> std::borrow::Cow<'_, str> {
    String::from_utf8_lossy(data)
}

// ---------------------------------------------------------------------------------------------
// points_file

/// The most points of a parsed table that are also hulled (keeps every input fast; the engine
/// target covers hulls on its own).
const POINTS_HULLED: usize = 40;

/// `pqhull_cli::points_file::parse_points` on any text. On success the table must be consistent,
/// hold only finite values, and print back (shortest round-trip form) to the same table; on error
/// the message must name a line that exists. Tables of dimension 2..=8 with at most
/// [`POINTS_HULLED`] points (and [`max_wide_points`] if their exponents are far apart) are then
/// hulled and checked as by the engine target ([`check_engine`], query at the origin).
pub fn points_file(data: &[u8]) {
    let text = text(data);
    match parse_points(&text) {
        Ok(table) => {
            let (d, n) = (table.dimension(), table.len());
            assert!(
                d >= 1 && n >= 1 && !table.is_empty(),
                "empty table {table:?}"
            );
            assert_eq!(table.coords().len(), d * n);
            assert_eq!(table.rows().len(), n);
            assert_eq!(table.lines().len(), n);
            assert!(table.coords().iter().all(|x| x.is_finite()));
            assert!(
                table.lines().windows(2).all(|w| w[0] < w[1]),
                "lines not increasing: {:?}",
                table.lines()
            );
            let line_count = text.split(['\n', '\r']).count();
            assert!(table.lines().iter().all(|&l| 1 <= l && l <= line_count));
            // Printed back, one row per line: the same values, bit for bit.
            let printed: String = table
                .rows()
                .map(|row| {
                    let fields: Vec<String> = row.iter().map(|x| format!("{x:?}")).collect();
                    fields.join(" ") + "\n"
                })
                .collect();
            let again = parse_points(&printed)
                .unwrap_or_else(|e| panic!("printed table does not parse: {e}\n{printed}"));
            assert_eq!(again.dimension(), d);
            let bits = |t: &pqhull_cli::points_file::PointTable| {
                t.coords().iter().map(|x| x.to_bits()).collect::<Vec<_>>()
            };
            assert_eq!(bits(&again), bits(&table), "round trip changed values");
            if n <= POINTS_HULLED {
                match d {
                    2 => hull_table::<2>(&table),
                    3 => hull_table::<3>(&table),
                    4 => hull_table::<4>(&table),
                    5 => hull_table::<5>(&table),
                    6 => hull_table::<6>(&table),
                    7 => hull_table::<7>(&table),
                    8 => hull_table::<8>(&table),
                    _ => assert!(table.to_arrays::<2>().is_none()),
                }
            }
        }
        Err(e) => {
            let message = e.to_string();
            assert!(!message.is_empty());
            if let Some(line) = e.line() {
                let line_count = text.split(['\n', '\r']).count();
                assert!(
                    1 <= line && line <= line_count,
                    "{message}: only {line_count} lines"
                );
                assert!(message.starts_with(&format!("line {line}: ")), "{message}");
            }
        }
    }
}

fn hull_table<const D: usize>(table: &pqhull_cli::points_file::PointTable) {
    let points = table.to_arrays::<D>().expect("the table's own dimension");
    // As in the engine target: few points when their exponents are far apart.
    if points.len() <= max_wide_points(D) || exponent_spread(&points) <= WIDE_SPREAD {
        check_engine(&points, None);
    }
}

// ---------------------------------------------------------------------------------------------
// grasp_json

/// Parsed grasps whose Q1 wrench set has at most this many points are also evaluated.
const WRENCHES_EVALUATED: usize = 256;

/// The grasp JSON reader (`split_grasps` then `parse_grasp`, as `pqh grasp`) on any text. Every
/// grasp read must be within the documented limits; small ones are evaluated (Q1 by the partial
/// and the full method), which must agree.
pub fn grasp_json(data: &[u8]) {
    let text = text(data);
    for value in split_grasps(&text) {
        let grasp = match value.and_then(|v| parse_grasp(&v)) {
            Ok(grasp) => grasp,
            Err(e) => {
                assert!(!e.to_string().is_empty());
                continue;
            }
        };
        let m = grasp.contact_count();
        let k = grasp.friction().cone_edges();
        assert!((1..=MAX_CONTACTS).contains(&m), "{m} contacts");
        assert!((MIN_CONE_EDGES..=MAX_CONE_EDGES).contains(&k), "{k} edges");
        let mu = grasp.friction().friction();
        assert!(mu.is_finite() && mu >= 0.0, "friction {mu}");
        let rho = grasp.torque_scale();
        assert!(rho.is_finite() && rho > 0.0, "torque scale {rho}");
        let wrenches: usize = grasp
            .contacts()
            .iter()
            .map(|c| if c.is_soft() { 2 * k } else { k })
            .sum();
        if wrenches <= WRENCHES_EVALUATED {
            evaluate_grasp(&grasp);
            every_metric(&grasp, wrenches);
        }
    }
}

/// `grasp` by `metric` and `method` through the one front door.
fn evaluate(grasp: &Grasp, metric: Metric, method: Method) -> Result<Evaluation, QualityError> {
    Evaluator::new(metric, method, None).and_then(|mut evaluator| evaluator.evaluate(grasp))
}

/// The value and the scale of a Q1 or Q∞ evaluation, which always has both.
fn value_and_scale(q: &Evaluation) -> (f64, f64) {
    (
        q.value.expect("Q1 and Q∞ have a value"),
        q.scale.expect("Q1 and Q∞ have a scale"),
    )
}

fn evaluate_grasp(grasp: &Grasp) {
    let partial = evaluate(grasp, Metric::Q1, Method::Partial);
    let full = evaluate(grasp, Metric::Q1, Method::Full);
    match (&partial, &full) {
        (Ok(p), Ok(f)) => {
            for q in [p, f] {
                let (value, _) = value_and_scale(q);
                assert!(!value.is_nan(), "NaN quality: {q:?}");
                assert!(!q.force_closure || value > 0.0, "{q:?}");
            }
            let ((p_value, p_scale), (f_value, f_scale)) = (value_and_scale(p), value_and_scale(f));
            // Both are within 1e-12 relative or 1e-14 · scale of the exact value.
            let tolerance = 1e-9 * p_scale.max(f_scale) + 1e-9 * p_value.abs();
            assert!(
                (p_value - f_value).abs() <= tolerance,
                "partial {} and full {} disagree (scale {})",
                p_value,
                f_value,
                p_scale
            );
        }
        (Err(p), Err(f)) => assert_eq!(p, f, "the methods fail differently"),
        _ => panic!("one method failed: partial {partial:?}, full {full:?}"),
    }
}

/// Q∞ sums of at most this many points are also evaluated by the full method, and wrench sets of
/// at most this many points get a volume (both hull the raw points with the exact engine).
const FULL_POINTS: usize = 64;

/// Every other metric through [`Evaluator`]: an error or a finite value (never NaN, never ±∞, which
/// JSON would print as null), never a panic; Q∞
/// by the partial and the full method agree on small sums.
fn every_metric(grasp: &Grasp, wrenches: usize) {
    let qinf = Metric::QInf {
        with_zero_wrench: false,
    };
    let resist = Metric::Resist {
        wrench: [0.0, 0.0, -1.0, 0.0, 0.0, 0.0],
    };
    for metric in [
        qinf,
        resist,
        Metric::SigmaMin,
        Metric::Isotropy,
        Metric::Volume,
    ] {
        if metric == Metric::Volume && wrenches > FULL_POINTS {
            continue;
        }
        if let Ok(score) = evaluate(grasp, metric, Method::Partial) {
            assert!(
                score.value.is_none_or(f64::is_finite),
                "{}: {score:?} for {}",
                metric.name(),
                pqhull::grasp::json::write_grasp(grasp)
            );
        }
    }
    if grasp
        .minkowski_points(false)
        .is_some_and(|n| n <= FULL_POINTS)
    {
        let partial = evaluate(grasp, qinf, Method::Partial);
        let full = evaluate(grasp, qinf, Method::Full);
        match (&partial, &full) {
            (Ok(p), Ok(f)) => {
                assert_eq!(p.force_closure, f.force_closure, "{p:?} vs {f:?}");
                let ((p_value, p_scale), (f_value, f_scale)) =
                    (value_and_scale(p), value_and_scale(f));
                let tolerance = 1e-9 * p_scale.max(f_scale) + 1e-9 * p_value.abs();
                assert!((p_value - f_value).abs() <= tolerance, "{p:?} vs {f:?}");
            }
            (Err(p), Err(f)) => assert_eq!(p, f, "the Q∞ methods fail differently"),
            _ => panic!("one Q∞ method failed: partial {partial:?}, full {full:?}"),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// mesh_obj, mesh_stl

/// Meshes with at most this many triangles also get an object wrench space (3 disturbance cones
/// of `k + 1` wrenches per triangle corner).
const TRIANGLES_FOR_OWS: usize = 64;

/// `Mesh::from_obj_reader` on any bytes.
pub fn mesh_obj(data: &[u8]) {
    if let Ok(mesh) = Mesh::from_obj_reader(data, "fuzz.obj") {
        use_mesh(&mesh);
    }
}

/// `Mesh::from_stl_reader` on any bytes (ASCII or binary STL).
pub fn mesh_stl(data: &[u8]) {
    if let Ok(mesh) = Mesh::from_stl_reader(std::io::Cursor::new(data), "fuzz.stl") {
        use_mesh(&mesh);
    }
}

/// Everything the library derives from a mesh, checked against the mesh's documented promises.
fn use_mesh(mesh: &Mesh) {
    let vertices = mesh.vertices();
    assert!(!vertices.is_empty() && !mesh.triangles().is_empty());
    assert!(vertices.iter().flatten().all(|x| x.is_finite()));
    assert!(
        mesh.triangles()
            .iter()
            .flatten()
            .all(|&i| (i as usize) < vertices.len())
    );
    let mass = mesh.mass_properties();
    assert!(
        mass.centre_of_mass.iter().all(|x| !x.is_nan())
            && !mass.surface_area.is_nan()
            && !mass.characteristic_length.is_nan()
            && mass.volume.is_none_or(|v| !v.is_nan()),
        "NaN mass properties {mass:?}"
    );
    assert!(mass.surface_area >= 0.0, "{mass:?}");
    let _ = (mesh.is_closed(), mesh.winding_reversed(), mesh.topology());
    for t in 0..mesh.triangles().len() {
        let area = mesh
            .triangle_area(t)
            .expect("an existing triangle has an area");
        assert!(area >= 0.0, "triangle {t}: area {area}");
        let normal = mesh.face_normal_inward(t);
        // A degenerate triangle has area 0 and no normal.
        assert!(
            normal.is_some() || area == 0.0,
            "triangle {t}: area {area}, no normal"
        );
        if let Some(n) = normal {
            let length = n.iter().map(|x| x * x).sum::<f64>().sqrt();
            assert!((length - 1.0).abs() < 1e-9, "triangle {t}: normal {n:?}");
        }
    }
    for n in mesh.vertex_normals_inward().into_iter().flatten() {
        let length = n.iter().map(|x| x * x).sum::<f64>().sqrt();
        assert!((length - 1.0).abs() < 1e-9, "vertex normal {n:?}");
    }
    let mut rng = pqhull::geometry::Rng::new(1);
    for p in mesh.sample_surface(&mut rng, 8) {
        assert!(
            p.position
                .iter()
                .chain(&p.inward_normal)
                .all(|x| x.is_finite())
        );
    }
    if mesh.triangles().len() <= TRIANGLES_FOR_OWS {
        let friction = FrictionModel::try_new(0.5, 4).expect("a valid model");
        if let Ok(space) = ObjectWrenchSpace::from_mesh(mesh, friction) {
            assert!(!space.is_empty());
            assert!(space.disturbances().iter().flatten().all(|x| x.is_finite()));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// engine

/// The most points of a set in dimension `d`: about 40, fewer in high dimensions, where a set of
/// points all on the hull has tens of thousands of facets and one input would take seconds.
pub fn max_points(d: usize) -> usize {
    match d {
        2..=4 => 40,
        5 | 6 => 30,
        _ => 20,
    }
}

/// The most points of a set in dimension `d` whose coordinates span more than [`WIDE_SPREAD`]
/// binary orders of magnitude. The engine decides such sets by exact arithmetic on integers of up
/// to ~2100 bits (when it cannot scale the input into [−1, 1] exactly, every predicate; otherwise
/// most): an 8-D hull of 18 such points takes seconds, so fewer are kept in high dimensions.
pub fn max_wide_points(d: usize) -> usize {
    match d {
        2 | 3 => 40,
        4 => 16,
        5 => 12,
        6 => 10,
        _ => d + 2,
    }
}

/// See [`max_wide_points`].
pub const WIDE_SPREAD: i32 = 128;

/// The binary exponents spanned by the non-zero finite coordinates of `points` (0 for none).
pub fn exponent_spread<const D: usize>(points: &[[f64; D]]) -> i32 {
    let exponents = points
        .iter()
        .flatten()
        .filter(|x| x.is_finite() && **x != 0.0)
        .map(|x| x.abs().log2().floor() as i32);
    let (lo, hi) = exponents.fold((i32::MAX, i32::MIN), |(lo, hi), e| (lo.min(e), hi.max(e)));
    if lo > hi { 0 } else { hi - lo }
}

/// A cursor over the fuzzer's bytes that reads zeros once they run out, so every input decodes.
struct Bytes<'a> {
    data: &'a [u8],
    at: usize,
}

impl Bytes<'_> {
    fn byte(&mut self) -> u8 {
        let b = self.data.get(self.at).copied().unwrap_or(0);
        self.at += 1;
        b
    }

    fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.byte(), self.byte()])
    }

    fn u64(&mut self) -> u64 {
        u64::from_le_bytes(std::array::from_fn(|_| self.byte()))
    }
}

/// `2^e` for any `e` in the range of finite non-zero `f64` powers of two (−1074..=1023).
fn pow2(e: i32) -> f64 {
    let e = e.clamp(-1074, 1023);
    if e >= -1022 {
        f64::from_bits(((e + 1023) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (e + 1074))
    }
}

/// Decodes one coordinate (axis `axis` of a point of `points`, the points so far).
fn coordinate<const D: usize>(
    bytes: &mut Bytes,
    points: &[[f64; D]],
    axis: usize,
    exponent: i32,
) -> f64 {
    let op = bytes.byte();
    let small = |b: u8| f64::from(i32::from(b % 9) - 4);
    match op % 10 {
        // Repeated coordinates: flats parallel to the axes.
        0 | 1 if !points.is_empty() => points[usize::from(bytes.byte()) % points.len()][axis],
        // Small integers times the set's scale: lattices, collinear and coplanar points.
        0..=3 => small(bytes.byte()) * pow2(exponent),
        4 => 0.0,
        // Extreme exponents, either sign: ±2^e for any e in −1074..=1023.
        5 => {
            let e = i32::from(bytes.u16() % 2098) - 1074;
            let sign = if bytes.byte() & 1 == 0 { 1.0 } else { -1.0 };
            sign * pow2(e)
        }
        // Subnormals and the smallest normals.
        6 => {
            let bits = bytes.u64() & ((1u64 << 53) - 1);
            let sign = if op & 0x80 == 0 { 1.0 } else { -1.0 };
            sign * f64::from_bits(bits)
        }
        // Any bit pattern (non-finite ones exercise the error path).
        7 => f64::from_bits(bytes.u64()),
        // A fraction near the set's scale: generic positions.
        _ => (f64::from(bytes.u16()) / 65536.0 - 0.5) * pow2(exponent + 1),
    }
}

/// Decodes a point set and a query point in dimension `D`.
fn decode<const D: usize>(bytes: &mut Bytes) -> (Vec<[f64; D]>, [f64; D]) {
    let n = usize::from(bytes.byte()) % (max_points(D) + 1);
    // The set's own scale: 2^e for e in −1074..=1023 (most sets near 1, see the weights).
    let exponent = match bytes.byte() % 4 {
        0 | 1 => i32::from(bytes.byte() % 8) - 4,
        _ => i32::from(bytes.u16() % 2098) - 1074,
    };
    let mut points: Vec<[f64; D]> = Vec::with_capacity(n);
    for _ in 0..n {
        let op = bytes.byte();
        let point = match op % 8 {
            // An exact duplicate.
            0 if !points.is_empty() => points[usize::from(bytes.byte()) % points.len()],
            // On the line through two earlier points (affine combination with a dyadic weight):
            // collinear and coplanar sets.
            1 if points.len() >= 2 => {
                let a = points[usize::from(bytes.byte()) % points.len()];
                let b = points[usize::from(bytes.byte()) % points.len()];
                let t = f64::from(i32::from(bytes.byte() % 9) - 2) / 4.0;
                std::array::from_fn(|i| a[i] + t * (b[i] - a[i]))
            }
            _ => {
                let mut p = [0.0; D];
                for (axis, c) in p.iter_mut().enumerate() {
                    *c = coordinate(bytes, &points, axis, exponent);
                }
                p
            }
        };
        points.push(point);
    }
    if exponent_spread(&points) > WIDE_SPREAD {
        points.truncate(max_wide_points(D));
    }
    let query = match bytes.byte() % 4 {
        // The origin (the grasp metrics' query).
        0 => [0.0; D],
        // An input point (on the boundary or inside).
        1 if !points.is_empty() => points[usize::from(bytes.byte()) % points.len()],
        _ => {
            let mut q = [0.0; D];
            for (axis, c) in q.iter_mut().enumerate() {
                *c = coordinate(bytes, &points, axis, exponent);
            }
            q
        }
    };
    (points, query)
}

/// The engine on a decoded point set: the first byte picks D in {2, …, 8}, the rest decodes up
/// to [`max_points`]`(D)` points (duplicates, points on flats, extreme exponents, subnormals,
/// zeros, the odd NaN; at most [`max_wide_points`]`(D)` when their exponents are far apart) and a
/// query point. See [`check_engine`] for what is checked.
pub fn engine(data: &[u8]) {
    let mut bytes = Bytes { data, at: 0 };
    match 2 + bytes.byte() % 7 {
        2 => engine_in::<2>(&mut bytes),
        3 => engine_in::<3>(&mut bytes),
        4 => engine_in::<4>(&mut bytes),
        5 => engine_in::<5>(&mut bytes),
        6 => engine_in::<6>(&mut bytes),
        7 => engine_in::<7>(&mut bytes),
        _ => engine_in::<8>(&mut bytes),
    }
}

fn engine_in<const D: usize>(bytes: &mut Bytes) {
    let (points, query) = decode::<D>(bytes);
    check_engine(
        &points,
        query.iter().all(|x| x.is_finite()).then_some(query),
    );
}

/// Whether every coordinate is zero or within `2^±400`: then the engine's power-of-two scaling
/// of the input (and of a query point among such values) is exact, and with it every sign the
/// hull reports.
fn moderate(values: impl IntoIterator<Item = f64>) -> bool {
    values
        .into_iter()
        .all(|x| x == 0.0 || (pow2(-400)..=pow2(400)).contains(&x.abs()))
}

/// Builds the full hull of `points` and the partial `ClosestToOrigin` hull towards `query` (the
/// origin when `None`), and checks:
///
/// * both fail, with the same typed error, or both succeed; an error is the right one (a
///   non-finite coordinate, fewer than D + 1 points, or points that do not span D dimensions —
///   the last confirmed: an affinely independent subset of D + 1 points never fails);
/// * both hulls pass [`Hull::check`];
/// * the full hull has no outside point, and along every axis its vertices reach the input's
///   extreme coordinates;
/// * the partial result's distance is not NaN (for coordinates up to `2^400`, whose squares do
///   not overflow) and, for inputs of moderate magnitude (exact signs), its sign is the query's
///   exact side of the full hull (inside, boundary, outside);
/// * the full hull's storage rebuilt for the points in reverse order passes the check.
pub fn check_engine<const D: usize>(points: &[[f64; D]], query: Option<[f64; D]>) {
    let query = query.unwrap_or([0.0; D]);
    let full = Hull::try_new(points);
    let partial = Hull::try_with_strategy(points, ClosestToOrigin::towards(query));
    let (mut full, (partial, result)) = match (full, partial) {
        (Ok(f), Ok(p)) => (f, p),
        (Err(f), Err(p)) => {
            assert_eq!(f, p, "the strategies reject the input differently");
            check_rejection(points, &f);
            return;
        }
        (f, p) => panic!(
            "one strategy failed: full {:?}, partial {:?}",
            f.err(),
            p.err()
        ),
    };
    if let Err(e) = full.check() {
        panic!("full hull of {points:?}: {e}");
    }
    if let Err(e) = partial.check() {
        panic!("partial hull of {points:?} towards {query:?}: {e}");
    }
    assert!(
        !full.has_outside_points(),
        "the full hull has outside points"
    );
    let vertices = full.vertex_indices();
    assert!(vertices.len() > D, "{} vertices", vertices.len());
    for axis in 0..D {
        for extreme in [f64::max, f64::min] {
            let all = points.iter().map(|p| p[axis]).reduce(extreme).unwrap();
            let hull = vertices
                .iter()
                .map(|&v| points[v][axis])
                .reduce(extreme)
                .unwrap();
            // `==`, not bits: the extreme may be 0.0 at one point and -0.0 at another.
            assert!(
                all == hull,
                "axis {axis}: the hull misses {all} (reaches {hull})"
            );
        }
    }
    let distance = result.signed_distance;
    // Never NaN, at any scale (the squared norms of the nearest-point search overflowed from
    // about 1e154 before the power-of-two units of issue 12 item 3).
    assert!(
        !distance.is_nan() && result.nearest_point.iter().all(|x| !x.is_nan()),
        "NaN distance towards {query:?} from the hull of {points:?}"
    );
    // The sign, where the distance is representable: subnormal inputs have distances that round
    // to 0 (an open rounding question: issue 12's closing note).
    if moderate(points.iter().flatten().chain(&query).copied()) {
        let sides: Vec<Sign> = full
            .facets()
            .map(|(id, _)| full.side_of(id, &query))
            .collect();
        let expected = if sides.contains(&Sign::Positive) {
            Sign::Negative // outside: negative distance
        } else if sides.contains(&Sign::Zero) {
            Sign::Zero
        } else {
            Sign::Positive
        };
        let got = if distance > 0.0 {
            Sign::Positive
        } else if distance < 0.0 {
            Sign::Negative
        } else {
            Sign::Zero
        };
        assert_eq!(
            got, expected,
            "signed distance {distance} towards {query:?} has the wrong sign"
        );
    }
    let reversed: Vec<[f64; D]> = points.iter().rev().copied().collect();
    full.rebuild_with_strategy(&reversed, FarthestPoint::new())
        .expect("the same points, reversed");
    if let Err(e) = full.check() {
        panic!("rebuilt hull of {reversed:?}: {e}");
    }
}

/// Checks that `error` is the right rejection of `points`.
fn check_rejection<const D: usize>(points: &[[f64; D]], error: &HullError) {
    let non_finite = points
        .iter()
        .enumerate()
        .find_map(|(i, p)| p.iter().position(|x| !x.is_finite()).map(|c| (i, c)));
    match *error {
        HullError::NonFinite { index, coordinate } => {
            assert_eq!(non_finite, Some((index, coordinate)), "{error}");
        }
        HullError::TooFewPoints { needed, got } => {
            assert!(
                non_finite.is_none(),
                "{error}, but a coordinate is not finite"
            );
            assert_eq!((needed, got), (D + 1, points.len()));
        }
        HullError::AffinelyDependent { rank, dimension } => {
            assert!(non_finite.is_none() && points.len() > D, "{error}");
            assert!(rank < D && dimension == D, "{error}");
            // The rank is a lower bound on the span: that many + 1 points, chosen by the engine,
            // must be affinely independent; D + 1 of the input's may not be (checked here on
            // subsets of small sets only: every subset is tried).
            if points.len() <= D + 3 {
                assert!(
                    !any_independent_simplex(points),
                    "{error}, but D + 1 of the points are affinely independent"
                );
            }
        }
        _ => panic!("unexpected error {error}"),
    }
}

/// Whether some D + 1 of `points` are affinely independent: each (D + 1)-subset is hulled on
/// its own (a simplex either builds or is rejected as affinely dependent).
fn any_independent_simplex<const D: usize>(points: &[[f64; D]]) -> bool {
    let n = points.len();
    let mut chosen: Vec<usize> = (0..=D).collect();
    loop {
        let simplex: Vec<[f64; D]> = chosen.iter().map(|&i| points[i]).collect();
        if Hull::try_new(&simplex).is_ok() {
            return true;
        }
        // Next combination in lexicographic order.
        let mut i = D + 1;
        loop {
            if i == 0 {
                return false;
            }
            i -= 1;
            if chosen[i] < n - (D + 1 - i) {
                break;
            }
        }
        chosen[i] += 1;
        for j in i + 1..=D {
            chosen[j] = chosen[j - 1] + 1;
        }
    }
}
