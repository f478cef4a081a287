//! The `--method` / `--methods` values, shared by `pqh grasp` and `pqh bench gws`.

use crate::error::CliError;
use clap::ValueEnum;
use pqhull::grasp::ows::OwsMethod;
use pqhull::grasp::quality::Method;

/// The `--method` values.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum MethodArg {
    /// Partial hull: stop once the nearest facet is certain (default)
    Partial,
    /// Full hull with pqhull's engine
    Full,
    /// Full hull with Qhull (needs the `qhull` feature)
    Qhull,
    /// OWS only: full hull, every disturbance against every facet
    Brute,
    /// OWS only: Borst et al.'s enclosing-ellipsoid approximation
    Ellipsoid,
}

/// The Q1 / Q∞ method for `arg`.
pub fn method(arg: MethodArg) -> Result<Method, CliError> {
    match arg {
        MethodArg::Partial => Ok(Method::Partial),
        MethodArg::Full => Ok(Method::Full),
        MethodArg::Qhull if cfg!(feature = "qhull") => Ok(Method::Qhull),
        MethodArg::Qhull => Err(CliError::Usage(
            "--method qhull needs pqh built with the `qhull` feature".into(),
        )),
        MethodArg::Brute | MethodArg::Ellipsoid => Err(CliError::Usage(
            "--method brute and ellipsoid are for --metric ows; q1 and qinf take partial, full \
             or qhull"
                .into(),
        )),
    }
}

/// The OWS method for `arg`.
pub fn ows_method(arg: MethodArg) -> Result<OwsMethod, CliError> {
    match arg {
        MethodArg::Partial => Ok(OwsMethod::Partial),
        MethodArg::Brute => Ok(OwsMethod::BruteForce),
        MethodArg::Ellipsoid => Ok(OwsMethod::Ellipsoid),
        MethodArg::Full | MethodArg::Qhull => Err(CliError::Usage(
            "--metric ows takes --method partial, brute or ellipsoid".into(),
        )),
    }
}
