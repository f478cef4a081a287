//! Why the built-in strategies choose, note and stop, as their traces record it: one typed
//! value per kind of step ([`TraceReason`]), put into words only when a run is traced. The codes
//! are stable for programs reading a trace; the words may change.

use super::SourceError;
use crate::hull::TraceReason;

/// The steps of [`ClosestToOrigin`](super::ClosestToOrigin) a trace records.
#[derive(Clone, Debug, PartialEq)]
pub enum NearestReason<const D: usize> {
    /// The queue's top facet: the query lies farthest beyond its plane (`distance` > 0), or
    /// beneath every queued plane, this one the nearest.
    Nearest {
        /// The query's floating-point distance beyond the plane.
        distance: f64,
    },
    /// The exact test found the query strictly beyond this facet: it is not yet inside.
    QueryBeyond {
        /// The query's floating-point distance beyond the plane.
        distance: f64,
    },
    /// Nothing lies beyond a facet the query is strictly beyond: the query is outside the full
    /// hull, and the search for the nearest point starts.
    Outside,
    /// The nearest point of the partial hull to the query, whose supporting plane is tested.
    NearestPoint,
    /// The point the facet holds is the farthest beyond the supporting plane through the
    /// nearest point: it is added.
    BeyondSupport {
        /// Its input index.
        point: usize,
        /// Its height beyond the plane.
        height: f64,
    },
    /// Nothing lies beyond the nearest facet and the query is inside (or on) every facet.
    InsideCertified {
        /// The certified distance.
        distance: f64,
        /// Whether the query is on the boundary.
        on_boundary: bool,
    },
    /// Nothing lies beyond the supporting plane through the nearest point: the query is outside.
    OutsideCertified {
        /// The certified distance.
        distance: f64,
    },
    /// A point source broke its contract; the run stops with this error.
    Failed(SourceError<D>),
}

impl<const D: usize> TraceReason for NearestReason<D> {
    fn code(&self) -> &'static str {
        match self {
            NearestReason::Nearest { .. } => "nearest-plane",
            NearestReason::QueryBeyond { .. } => "query-beyond",
            NearestReason::Outside => "query-outside",
            NearestReason::NearestPoint => "nearest-point",
            NearestReason::BeyondSupport { .. } => "beyond-support",
            NearestReason::InsideCertified { .. } => "inside-certified",
            NearestReason::OutsideCertified { .. } => "outside-certified",
            NearestReason::Failed(_) => "source-error",
        }
    }

    fn describe(&self) -> String {
        match self {
            NearestReason::Nearest { distance } if *distance > 0.0 => {
                "the query lies farthest beyond this facet's plane".to_string()
            }
            NearestReason::Nearest { .. } => {
                "nearest plane to the query (the query is beneath every queued plane)".to_string()
            }
            NearestReason::QueryBeyond { .. } => "the query is strictly beyond this facet (exact \
                                                  test): it is not yet inside the partial hull"
                .to_string(),
            NearestReason::Outside => "nothing lies beyond this facet and the query is strictly \
                                       beyond it: the query is outside the full hull; searching \
                                       for the nearest point"
                .to_string(),
            NearestReason::NearestPoint => "nearest point of the partial hull to the query: does \
                                            anything lie beyond the supporting plane through it?"
                .to_string(),
            NearestReason::BeyondSupport { point, .. } => format!(
                "holds point {point}, the farthest beyond the supporting plane through the \
                 nearest point: it is added"
            ),
            NearestReason::InsideCertified {
                distance,
                on_boundary,
            } => {
                let side = if *on_boundary {
                    "query on the boundary"
                } else {
                    "query inside"
                };
                format!(
                    "nothing lies beyond the nearest facet and the query is inside every facet: \
                     distance {distance} certified ({side})"
                )
            }
            NearestReason::OutsideCertified { distance } => format!(
                "nothing lies beyond the supporting plane through the nearest point: distance \
                 {distance} certified (query outside)"
            ),
            NearestReason::Failed(error) => format!("stopped: {error}"),
        }
    }

    fn key(&self) -> Option<(&'static str, f64)> {
        match self {
            NearestReason::Nearest { distance } | NearestReason::QueryBeyond { distance } => {
                Some(("distance of the query beyond the plane", *distance))
            }
            NearestReason::BeyondSupport { height, .. } => {
                Some(("height of the point beyond the supporting plane", *height))
            }
            _ => None,
        }
    }
}

/// The steps of [`OwsInflation`](super::OwsInflation) a trace records.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum InflationReason {
    /// The origin is strictly inside the partial hull: the disturbances are inflated.
    OriginInside,
    /// The origin is on or beyond this facet's plane (the farthest beyond first).
    OriginBeyond {
        /// The origin's floating-point distance beyond the plane.
        distance: f64,
    },
    /// Nothing lies beyond a facet with the origin on or beyond its plane: not force closure.
    NotForceClosure,
    /// The smallest inflation factor: this disturbance reaches this facet's plane first.
    Smallest {
        /// The disturbance's index.
        disturbance: usize,
        /// Its inflation factor.
        factor: f64,
    },
    /// Nothing lies beyond the facet with the smallest inflation factor: the value is certified.
    Certified {
        /// The deciding disturbance's index.
        disturbance: usize,
        /// The value (its inflation factor).
        value: f64,
    },
    /// Every disturbance is zero: nothing reaches any facet, the value is infinite.
    NoDisturbance,
}

impl TraceReason for InflationReason {
    fn code(&self) -> &'static str {
        match self {
            InflationReason::OriginInside => "origin-inside",
            InflationReason::OriginBeyond { .. } => "origin-beyond",
            InflationReason::NotForceClosure => "not-force-closure",
            InflationReason::Smallest { .. } => "smallest-factor",
            InflationReason::Certified { .. } => "certified",
            InflationReason::NoDisturbance => "no-disturbance",
        }
    }

    fn describe(&self) -> String {
        match self {
            InflationReason::OriginInside => "the origin is strictly inside the partial hull \
                                              (exact tests): inflating the disturbances"
                .to_string(),
            InflationReason::OriginBeyond { .. } => {
                "the origin is on or beyond this facet's plane (farthest beyond first)".to_string()
            }
            InflationReason::NotForceClosure => "nothing lies beyond a facet with the origin on \
                                                 or beyond its plane: not force closure (no value)"
                .to_string(),
            InflationReason::Smallest { disturbance, .. } => format!(
                "smallest inflation factor (disturbance {disturbance} reaches this facet's plane \
                 first)"
            ),
            InflationReason::Certified { disturbance, value } => format!(
                "nothing lies beyond the facet with the smallest inflation factor: Q = {value} \
                 certified (disturbance {disturbance})"
            ),
            InflationReason::NoDisturbance => {
                "no disturbance reaches any facet (every disturbance is zero): Q = infinity"
                    .to_string()
            }
        }
    }

    fn key(&self) -> Option<(&'static str, f64)> {
        match self {
            InflationReason::OriginBeyond { distance } => {
                Some(("distance of the origin beyond the plane", *distance))
            }
            InflationReason::Smallest { factor, .. } => Some(("inflation factor", *factor)),
            _ => None,
        }
    }
}
