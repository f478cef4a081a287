//! Fig. 10 and Fig. 12 (with Table 1's quantity): grasps sampled on the built-in object the way
//! `pqh plan` samples them ([`samples`]), scored by Q1 and by Q_OWS.
//!
//! `pqh plan` is the paper's random sampler of Fig. 12 (sample contacts, keep the best grasp),
//! not the planner behind its Table 1; Table 1's quantity here is the same one the sampler
//! measures: the time spent evaluating grasp quality by the partial hull against the full hull.

use super::{
    Comparison, Figure, FigureId, PAPER_NOT_QUOTED, Progress, ReproduceError, Size, Table,
};
use crate::bench::stats::{median, micros};
use crate::object::{DEFAULT_OBJECT_NAME, default_object};
use pqhull::grasp::ows::ObjectWrenchSpace;
use pqhull::grasp::{Evaluator, FrictionModel, Method, Metric};
use pqhull::mesh::Mesh;
use pqhull::plan::samples;

/// Contacts per grasp.
pub const CONTACTS: usize = 4;
/// Cone edges of the grasps and of the object wrench space.
pub const EDGES: usize = 8;
/// Friction coefficient of both.
pub const FRICTION: f64 = 0.5;

/// One score of one sample: µs, value (NaN when not force closure).
struct Scored {
    time_us: Vec<f64>,
    value: Vec<f64>,
}

/// Scores `n` samples by `metric` with `method`; `space` for Q_OWS.
/// The built-in object, its friction model and its wrench space: built once per figure.
struct Object {
    mesh: Mesh,
    friction: FrictionModel,
    space: ObjectWrenchSpace,
}

impl Object {
    fn new() -> Result<Object, ReproduceError> {
        let fail = |e: String| ReproduceError::Experiment(e);
        let mesh = default_object();
        let friction = FrictionModel::try_new(FRICTION, EDGES).map_err(|e| fail(e.to_string()))?;
        let space =
            ObjectWrenchSpace::from_mesh(&mesh, friction).map_err(|e| fail(e.to_string()))?;
        Ok(Object {
            mesh,
            friction,
            space,
        })
    }
}

fn score(
    object: &Object,
    n: usize,
    seed: u64,
    metric: Metric,
    method: Method,
    progress: Progress<'_>,
) -> Result<Scored, ReproduceError> {
    let fail = |e: String| ReproduceError::Experiment(e);
    let Object {
        mesh,
        friction,
        space,
    } = object;
    let label = format!("{} by {}", metric.name(), method.name());
    let space_of_metric = (metric == Metric::Ows).then_some(space);
    let mut evaluator = Evaluator::new(metric, method, space_of_metric)
        .map_err(|e| fail(format!("{label}: {e}")))?;
    let mut scored = Scored {
        time_us: Vec::with_capacity(n),
        value: Vec::with_capacity(n),
    };
    progress(&label, 0, n);
    for (i, grasp) in samples(mesh, Some(space), CONTACTS, *friction, seed)
        .take(n)
        .enumerate()
    {
        let grasp = grasp.map_err(|e| fail(format!("sample {i}: {e}")))?;
        let q = evaluator
            .evaluate(&grasp)
            .map_err(|e| fail(format!("{label}, sample {i}: {e}")))?;
        let (elapsed, closure, value) = (
            q.stats.elapsed,
            q.force_closure,
            q.value.unwrap_or(f64::NAN),
        );
        scored.time_us.push(micros(elapsed));
        scored.value.push(if closure { value } else { f64::NAN });
        progress(&label, i + 1, n);
    }
    Ok(scored)
}

/// The sample with the largest value (NaN never wins), or None.
fn best(values: &[f64]) -> Option<usize> {
    (0..values.len())
        .filter(|&i| !values[i].is_nan())
        .max_by(|&a, &b| values[a].total_cmp(&values[b]))
}

fn differences(samples: usize) -> Vec<String> {
    vec![
        format!(
            "Object: {DEFAULT_OBJECT_NAME}; {samples} samples of {CONTACTS} contacts by area on its surface (inward face normals), μ = {FRICTION}, k = {EDGES} for the grasps and the object wrench space; torque about the centre of mass, scaled by the largest vertex distance."
        ),
        "The sampler is `pqh plan`'s: the paper's random sampler of Fig. 12, not the planner of its Table 1.".to_string(),
        "Times are wall clock on this machine (see docs/paper.md for which); the full-hull methods are this crate's, with exact orientations.".to_string(),
    ]
}

/// Fig. 10: Q1 and Q_OWS of the same samples, and which grasp each metric ranks best.
///
/// # Errors
/// [`ReproduceError::Experiment`] when an evaluation fails.
pub fn fig10(size: Size, seed: u64, progress: Progress<'_>) -> Result<Figure, ReproduceError> {
    let (sets, n) = match size {
        Size::Smoke => (2, 20),
        Size::Default => (10, 300),
        Size::Full => (20, 1000),
    };
    let object = Object::new()?;
    let rank = |values: &[f64], i: usize| {
        1 + values
            .iter()
            .filter(|v| !v.is_nan() && **v > values[i])
            .count()
    };
    let mut table = Table::new("fig10");
    let mut columns: [Vec<f64>; 6] = Default::default();
    let (mut differ, mut compared, mut closure) = (0, 0, 0);
    let (mut ows_ranks, mut q1_ranks) = (Vec::new(), Vec::new());
    for set in 0..sets {
        let set_seed = seed.wrapping_add(set as u64);
        let q1 = score(
            &object,
            n,
            set_seed,
            Metric::Q1,
            Method::Partial,
            &mut *progress,
        )?;
        let ows = score(
            &object,
            n,
            set_seed,
            Metric::Ows,
            Method::Partial,
            &mut *progress,
        )?;
        let (b1, bo) = (best(&q1.value), best(&ows.value));
        if let (Some(a), Some(b)) = (b1, bo) {
            compared += 1;
            differ += usize::from(a != b);
            ows_ranks.push(rank(&ows.value, a) as f64);
            q1_ranks.push(rank(&q1.value, b) as f64);
        }
        closure += q1.value.iter().filter(|v| !v.is_nan()).count();
        let mark = |b: Option<usize>| (0..n).map(move |i| f64::from(u8::from(b == Some(i))));
        columns[0].extend(std::iter::repeat_n(set_seed as f64, n));
        columns[1].extend((0..n).map(|i| i as f64));
        columns[2].extend(q1.value);
        columns[3].extend(ows.value);
        columns[4].extend(mark(b1));
        columns[5].extend(mark(bo));
    }
    for (name, values) in ["seed", "sample", "q1", "ows", "q1_best", "ows_best"]
        .iter()
        .zip(columns)
    {
        table = table.numbers(name, values);
    }
    let comparisons = vec![
        Comparison::new(
            "the Q1-best and the OWS-best grasp of a sample set differ",
            "yes (the figure's example)",
            format!("in {differ} of {compared} sample sets"),
        ),
        Comparison::new(
            "Q_OWS rank of the Q1-best grasp, median over the sets",
            PAPER_NOT_QUOTED,
            format!("{}", median(&mut ows_ranks)),
        ),
        Comparison::new(
            "Q1 rank of the OWS-best grasp, median over the sets",
            PAPER_NOT_QUOTED,
            format!("{}", median(&mut q1_ranks)),
        ),
        Comparison::new(
            "force-closure samples",
            PAPER_NOT_QUOTED,
            format!("{closure} of {}", sets * n),
        ),
    ];
    let mut differences = differences(n);
    differences.insert(
        1,
        format!(
            "{sets} sample sets (seeds {seed} to {}); each set's best grasps are marked.",
            seed.wrapping_add(sets as u64 - 1)
        ),
    );
    Ok(Figure {
        id: FigureId::Fig10,
        title: format!("Q1 against Q_OWS: {sets} sets of {n} sampled grasps"),
        tables: vec![table],
        comparisons,
        differences,
    })
}

/// Fig. 12 and Table 1: the time each metric's quality evaluation takes per sample, by the
/// partial and by the full hull, over the same samples.
///
/// # Errors
/// As [`fig10`].
pub fn fig12(size: Size, seed: u64, progress: Progress<'_>) -> Result<Figure, ReproduceError> {
    let n = match size {
        Size::Smoke => 8,
        Size::Default => 100,
        Size::Full => 300,
    };
    let object = Object::new()?;
    let runs = [
        (Metric::Q1, Method::Partial),
        (Metric::Q1, Method::Full),
        (Metric::Ows, Method::Partial),
        (Metric::Ows, Method::Full),
    ];
    let mut scored = Vec::new();
    for (metric, method) in runs {
        scored.push(score(&object, n, seed, metric, method, &mut *progress)?);
    }
    let total = |s: &Scored| s.time_us.iter().sum::<f64>();
    let speedup = |full: &Scored, partial: &Scored| total(full) / total(partial);
    let agree = |a: &Scored, b: &Scored| {
        let same_best = best(&a.value) == best(&b.value);
        let worst = a
            .value
            .iter()
            .zip(&b.value)
            .filter(|(x, y)| !x.is_nan() && !y.is_nan())
            .map(|(x, y)| (x - y).abs() / y.abs())
            .fold(0.0, f64::max);
        format!(
            "{}; largest relative difference {worst:.1e}",
            if same_best {
                "same best grasp"
            } else {
                "DIFFERENT best grasps"
            }
        )
    };
    let comparisons = vec![
        Comparison::new(
            "quality-evaluation time, full / partial, Q1",
            "19–39× (Table 1, over its planners and objects)",
            format!("{:.1}×", speedup(&scored[1], &scored[0])),
        ),
        Comparison::new(
            "quality-evaluation time, full / partial, Q_OWS",
            "19–39× (Table 1, over its planners and objects)",
            format!("{:.1}×", speedup(&scored[3], &scored[2])),
        ),
        Comparison::new(
            "partial and full agree (Q1)",
            "— (same metric, exact)",
            agree(&scored[0], &scored[1]),
        ),
        Comparison::new(
            "partial and full agree (Q_OWS)",
            "— (same metric, exact)",
            agree(&scored[2], &scored[3]),
        ),
    ];
    let mut table = Table::new("fig12").numbers("sample", (0..n).map(|i| i as f64).collect());
    for ((metric, method), s) in runs.iter().zip(&scored) {
        let name = format!("{}_{}", metric.name(), method.name());
        table = table
            .numbers(&format!("{name}_us"), s.time_us.clone())
            .numbers(&format!("{name}_value"), s.value.clone());
    }
    Ok(Figure {
        id: FigureId::Fig12,
        title: format!("Planning by random sampling: {n} samples, each metric, partial and full"),
        tables: vec![table],
        comparisons,
        differences: differences(n),
    })
}
