//! The `--metric` and `--method` values: one enum each, the library's [`Metric`] and [`Method`]
//! under the names `pqh` prints, shared by `pqh grasp`, `pqh plan` and `pqh bench gws`.

use crate::error::CliError;
use clap::ValueEnum;
use pqhull::grasp::quality::{Method, Metric};

/// The `--metric` values of `pqh grasp` and `pqh plan`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MetricArg {
    /// Ferrari–Canny Q1 over the union of contact wrenches
    Q1,
    /// Q∞ over the Minkowski sum (implicit for the partial method)
    Qinf,
    /// Object wrench space metric (needs the object: --mesh, or --disturbances in pqh grasp)
    Ows,
    /// The largest multiple t of one wrench such that the grasp resists -t·wrench (--wrench; Q_OWS
    /// with that single disturbance)
    Resist,
    /// Volume of the grasp wrench space (the full hull: a volume needs every facet; --method
    /// decides only the force-closure verdict)
    Volume,
    /// Smallest singular value of the grasp matrix (--method decides only the verdict)
    SigmaMin,
    /// Isotropy index of the grasp matrix: smallest over largest singular value (--method
    /// decides only the verdict)
    Isotropy,
}

impl MetricArg {
    /// The library's metric: `zero_wrench` is Q∞ with the zero wrench in every contact's set,
    /// `wrench` the text of `--wrench` (`fx,fy,fz,tx,ty,tz`), which `resist` needs and only it
    /// takes.
    pub fn metric(self, zero_wrench: bool, wrench: Option<&str>) -> Result<Metric, CliError> {
        if zero_wrench && self != MetricArg::Qinf {
            return Err(CliError::Usage("--zero-wrench is for --metric qinf".into()));
        }
        if wrench.is_some() && self != MetricArg::Resist {
            return Err(CliError::Usage("--wrench is for --metric resist".into()));
        }
        Ok(match self {
            MetricArg::Q1 => Metric::Q1,
            MetricArg::Qinf => Metric::QInf {
                with_zero_wrench: zero_wrench,
            },
            MetricArg::Ows => Metric::Ows,
            MetricArg::Resist => {
                let text = wrench.ok_or_else(|| {
                    CliError::Usage("--metric resist needs --wrench fx,fy,fz,tx,ty,tz".into())
                })?;
                let w = crate::input::parse_point("--wrench", text)?;
                let wrench = w.as_slice().try_into().map_err(|_| {
                    CliError::Usage(format!("--wrench needs 6 numbers, not {}", w.len()))
                })?;
                Metric::Resist { wrench }
            }
            MetricArg::Volume => Metric::Volume,
            MetricArg::SigmaMin => Metric::SigmaMin,
            MetricArg::Isotropy => Metric::Isotropy,
        })
    }
}

/// The `--method` values (which metric takes which: `Method::supports`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    /// Partial hull: stop once the answer is certain (every metric; the default)
    Partial,
    /// Full hull with pqhull's engine (every metric; for ows the brute force, alias `brute`)
    #[value(alias = "brute")]
    Full,
    /// Full hull with Qhull (q1, qinf; needs the `qhull` feature)
    Qhull,
    /// Partial hull, disturbances assigned by ray as Algorithm 2 is published (ows)
    PartialRays,
    /// Borst et al.'s enclosing-ellipsoid approximation (ows; not exact)
    Ellipsoid,
}

impl MethodArg {
    fn method(self) -> Method {
        match self {
            MethodArg::Partial => Method::Partial,
            MethodArg::Full => Method::Full,
            MethodArg::Qhull => Method::Qhull,
            MethodArg::PartialRays => Method::PartialRays,
            MethodArg::Ellipsoid => Method::Ellipsoid,
        }
    }
}

/// The `--methods` values of `pqh bench gws`: the methods that compute Q1 (only these are
/// listed, so the help shows exactly what is accepted).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum GwsMethodArg {
    /// Partial hull
    Partial,
    /// Full hull with pqhull's engine
    Full,
    /// Full hull with Qhull (needs the `qhull` feature)
    Qhull,
}

impl GwsMethodArg {
    /// The library's method, or a usage error for Qhull in a build without it.
    pub fn method(self) -> Result<Method, CliError> {
        match self {
            GwsMethodArg::Partial => Ok(Method::Partial),
            GwsMethodArg::Full => Ok(Method::Full),
            GwsMethodArg::Qhull => available(Method::Qhull),
        }
    }
}

/// `--method` for `metric`: a usage error naming what the metric takes when it does not take
/// this one, or when it is Qhull in a build without the `qhull` feature.
pub fn method_for(arg: MethodArg, metric: Metric) -> Result<Method, CliError> {
    let method = arg.method();
    if !method.supports(metric) {
        let takes: Vec<&str> = MethodArg::value_variants()
            .iter()
            .filter(|m| m.method().supports(metric))
            .map(|m| m.method().name())
            .collect();
        return Err(CliError::Usage(format!(
            "--metric {} takes --method {}, not {}",
            metric.name(),
            takes.join(", "),
            method.name()
        )));
    }
    available(method)
}

fn available(method: Method) -> Result<Method, CliError> {
    if method == Method::Qhull && !cfg!(feature = "qhull") {
        return Err(CliError::Usage(
            "--method qhull needs pqh built with the `qhull` feature".into(),
        ));
    }
    Ok(method)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every `--metric` and `--method` value is the library's name for what it maps to, so the
    /// CLI, the library and Python read one vocabulary.
    #[test]
    fn the_values_are_the_library_names() {
        for arg in MethodArg::value_variants() {
            let name = arg
                .to_possible_value()
                .expect("not skipped")
                .get_name()
                .to_string();
            assert_eq!(name.parse::<Method>(), Ok(arg.method()), "--method {name}");
        }
        assert_eq!("brute".parse::<Method>(), Ok(MethodArg::Full.method()));
        for arg in GwsMethodArg::value_variants() {
            let name = arg
                .to_possible_value()
                .expect("not skipped")
                .get_name()
                .to_string();
            let method: Method = name.parse().expect("a library method");
            if let Ok(m) = arg.method() {
                assert_eq!(m, method, "--methods {name}");
            }
        }
        for arg in MetricArg::value_variants() {
            let name = arg
                .to_possible_value()
                .expect("not skipped")
                .get_name()
                .to_string();
            let wrench = (*arg == MetricArg::Resist).then_some("1,0,0,0,0,0");
            let metric = arg.metric(false, wrench).expect("a metric");
            assert_eq!(metric.name(), name, "--metric {name}");
            if *arg != MetricArg::Resist {
                assert_eq!(name.parse::<Metric>(), Ok(metric), "--metric {name}");
            }
        }
    }
}
