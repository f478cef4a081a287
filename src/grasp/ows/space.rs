//! The disturbance set: an object's wrench space from a mesh, or a given task wrench space.

use crate::geometry::SupportIndex;
use crate::geometry::ellipsoid::{CentredEllipsoid, EllipsoidError};
use crate::geometry::vector::{cross, normalize, sub};
use crate::grasp::{Contact, FrictionModel, Grasp, GraspError};
use crate::hull::{Hull, HullError};
use crate::mesh::{CentreKind, Mesh};
use serde_json::{Value, json};
use std::collections::HashSet;
use std::fmt;
use std::sync::OnceLock;

/// The stopping tolerance of the approximate method's ellipsoid: its volume is within a factor
/// (1 + ε)^3 of the minimum ([`CentredEllipsoid::try_enclosing`]), and it contains every
/// disturbance exactly whatever ε.
pub const ELLIPSOID_TOLERANCE: f64 = crate::geometry::ellipsoid::DEFAULT_TOLERANCE;

/// The most disturbances [`ObjectWrenchSpace::from_mesh`] reserves room for up front (2^20
/// wrenches, 48 MiB); a larger set grows as it is built.
const RESERVE_CAP: usize = 1 << 20;

/// Where an [`ObjectWrenchSpace`] came from.
#[derive(Clone, Debug, PartialEq)]
pub enum SpaceOrigin {
    /// Built from a mesh ([`ObjectWrenchSpace::from_mesh`]).
    Mesh {
        /// The torque reference: the mesh's centre of mass.
        centre_of_mass: [f64; 3],
        /// Whether that is the solid's centre or (open mesh) the surface centroid.
        centre_kind: CentreKind,
        /// The torque scale ρ: the largest distance from the centre to a vertex.
        characteristic_length: f64,
        /// Friction coefficient of the disturbance cones.
        friction: f64,
        /// Rim edges k of each triangle's disturbance cone (each corner also gets the normal
        /// push).
        cone_edges: usize,
    },
    /// Given as explicit disturbance wrenches (a task wrench space), already in the grasps' units.
    Given,
}

/// The disturbances a grasp must resist: an object wrench space, or any task wrench space.
///
/// Prepared once per object and shared by every grasp evaluated against it (it is `Sync`; the
/// ellipsoid of the approximate method is computed on first use and cached). Serialisable with
/// [`to_json`](Self::to_json) / [`from_json`](Self::from_json), so a planner can cache it.
#[derive(Debug)]
pub struct ObjectWrenchSpace {
    disturbances: Vec<[f64; 6]>,
    /// The disturbances' support function, for the partial method.
    index: SupportIndex<6>,
    origin: SpaceOrigin,
    vertices_without_normal: usize,
    triangles_skipped: usize,
    reduced: bool,
    ellipsoid: OnceLock<Result<CentredEllipsoid<6>, EllipsoidError>>,
}

impl Clone for ObjectWrenchSpace {
    fn clone(&self) -> Self {
        ObjectWrenchSpace {
            disturbances: self.disturbances.clone(),
            index: self.index.clone(),
            origin: self.origin.clone(),
            vertices_without_normal: self.vertices_without_normal,
            triangles_skipped: self.triangles_skipped,
            reduced: self.reduced,
            ellipsoid: OnceLock::new(),
        }
    }
}

/// The most distinct disturbances an [`ObjectWrenchSpace`] holds: 2^23 (384 MB of wrenches, about
/// as much again for the set that removes repeats while a mesh's are made). Spot (2,930 triangles)
/// has 158,112 at k = 8 and would need about 18 million at k = 1024.
pub const MAX_DISTURBANCES: usize = 1 << 23;

/// Why an [`ObjectWrenchSpace`] could not be built or read.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum OwsError {
    /// No disturbance at all (an empty set, or a mesh none of whose triangles is usable).
    Empty,
    /// Every disturbance is the zero wrench: Q_OWS, the largest r with −r·d in the grasp wrench
    /// space for every disturbance d, would be unbounded for every force-closure grasp.
    AllZero,
    /// More distinct disturbances than [`MAX_DISTURBANCES`] (a large mesh with many cone edges).
    TooManyDisturbances {
        /// The limit, [`MAX_DISTURBANCES`].
        max: usize,
    },
    /// Disturbance `index` has a NaN or infinite coordinate.
    NonFinite {
        /// Its index in the given set.
        index: usize,
    },
    /// The friction model or a disturbance contact was invalid.
    Grasp(GraspError),
    /// The mesh's characteristic length is zero (all vertices at the centre).
    DegenerateMesh,
    /// A serialised space was malformed.
    Json(String),
}

impl fmt::Display for OwsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OwsError::Empty => write!(f, "the disturbance set is empty"),
            OwsError::TooManyDisturbances { max } => write!(
                f,
                "more than {max} distinct disturbances (a mesh's 3·(k + 1) per triangle): use \
                 fewer cone edges or a coarser mesh"
            ),
            OwsError::AllZero => write!(
                f,
                "every disturbance is the zero wrench, against which Q_OWS is unbounded"
            ),
            OwsError::NonFinite { index } => {
                write!(f, "disturbance {index} has a NaN or infinite coordinate")
            }
            OwsError::Grasp(e) => write!(f, "{e}"),
            OwsError::DegenerateMesh => write!(
                f,
                "the mesh has no extent: every vertex is at its centre of mass"
            ),
            OwsError::Json(message) => write!(f, "malformed object wrench space: {message}"),
        }
    }
}

impl std::error::Error for OwsError {}

impl From<GraspError> for OwsError {
    fn from(e: GraspError) -> Self {
        OwsError::Grasp(e)
    }
}

impl ObjectWrenchSpace {
    /// The object wrench space of `mesh` with `friction`'s cones: the seed paper's Eq. 6,
    /// discretised.
    ///
    /// For every non-degenerate triangle (corners `v0, v1, v2` as listed):
    ///
    /// * `n` is its unit inward normal ([`Mesh::face_normal_inward`]) — the triangle's own, never
    ///   an average over the faces around a vertex;
    /// * `t` is its first edge `v1 − v0` with the component along `n` removed, normalised (as a
    ///   [`Contact`] with that tangent does it): one intrinsic orientation for the cone, shared by
    ///   the triangle's three corners;
    /// * the unit disturbance forces are the normal push `n` and the `k` unit rim edges
    ///   `e_j = (n + μ(cos θ_j t + sin θ_j (n × t))) / |n + μ(cos θ_j t + sin θ_j (n × t))|`,
    ///   θ_j = 2πj/k (the angles of [`FrictionModel`]'s edges);
    /// * at each corner `v` of the triangle every such force `e` gives the wrench
    ///   `[e ; (v − c) × e / ρ]`, with `c` the centre of mass and ρ the characteristic length
    ///   ([`MassProperties`](crate::mesh::MassProperties)).
    ///
    /// So a mesh with `T` usable triangles gives at most `3 T (k + 1)` disturbances, in triangle
    /// order (corner 0, 1, 2; for each corner the push, then `e_0 … e_(k−1)`). Wrenches exactly
    /// equal to an earlier one (a corner shared by coplanar triangles gets the same push from
    /// each, and the same rim too when their `t` agree) are kept once, at their first position.
    /// This is a discretisation: a unit force strictly between the push and the rim, or between
    /// two rim edges, lies on the unit sphere slightly outside the hull of these `k + 1` and is
    /// not represented (further rings of the cap would refine it; none are built).
    ///
    /// Degenerate triangles (no inward normal: a repeated index or collinear corners, see the
    /// [mesh conventions](crate::mesh)) are skipped and counted
    /// ([`triangles_skipped`](Self::triangles_skipped)); so are vertices that are a corner of no
    /// usable triangle ([`vertices_without_normal`](Self::vertices_without_normal)).
    ///
    /// ```
    /// use pqhull::grasp::FrictionModel;
    /// use pqhull::grasp::ows::ObjectWrenchSpace;
    /// use pqhull::mesh::Mesh;
    ///
    /// let cube = Mesh::cuboid([0.5, 0.5, 0.5])?;
    /// let ows = ObjectWrenchSpace::from_mesh(&cube, FrictionModel::try_new(0.5, 4)?)?;
    /// // Each face is two triangles whose first edges (a side, a diagonal) differ by 45°: per
    /// // face, 4 corner pushes (the two corners on the diagonal are shared) and 2 × 3 × 4 rim
    /// // edges (no two rims coincide at k = 4).
    /// assert_eq!(ows.len(), 6 * (4 + 2 * 3 * 4));
    /// // Unit forces: the force part of every disturbance has length 1.
    /// for d in ows.disturbances() {
    ///     assert!(((d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() - 1.0).abs() < 1e-15);
    /// }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`OwsError::Empty`] when no triangle is usable; [`OwsError::DegenerateMesh`] when ρ = 0;
    /// [`OwsError::TooManyDisturbances`] beyond [`MAX_DISTURBANCES`], found before the set grows
    /// past it.
    pub fn from_mesh(mesh: &Mesh, friction: FrictionModel) -> Result<Self, OwsError> {
        Self::from_mesh_at_most(mesh, friction, MAX_DISTURBANCES)
    }

    /// [`from_mesh`](Self::from_mesh) with at most `max` distinct disturbances.
    fn from_mesh_at_most(
        mesh: &Mesh,
        friction: FrictionModel,
        max: usize,
    ) -> Result<Self, OwsError> {
        let mass = mesh.mass_properties();
        let rho = mass.characteristic_length;
        if !(rho > 0.0 && rho.is_finite()) {
            return Err(OwsError::DegenerateMesh);
        }
        let c = mass.centre_of_mass;
        let vertices = mesh.vertices();
        let k = friction.cone_edges();
        // The upper bound 3T(k + 1), saturating; the reservation is capped so that a huge k
        // cannot make it request memory the set will never need (it grows as needed past that).
        let bound = mesh
            .triangles()
            .len()
            .saturating_mul(k.saturating_add(1))
            .saturating_mul(3);
        let reserve = bound.min(RESERVE_CAP);
        let mut disturbances: Vec<[f64; 6]> = Vec::with_capacity(reserve);
        // Exact equality of wrenches, through their bit patterns (with −0 read as +0, which
        // compares equal to it); every coordinate is finite, so no NaN is involved.
        let mut seen: HashSet<[u64; 6]> = HashSet::with_capacity(reserve);
        let mut used = vec![false; vertices.len()];
        let mut triangles_skipped = 0;
        // The unit forces of the current triangle: the push, then the k rim edges.
        let mut forces: Vec<[f64; 3]> = Vec::with_capacity(k.saturating_add(1).min(RESERVE_CAP));
        for (index, &triangle) in mesh.triangles().iter().enumerate() {
            let Some(n) = mesh.face_normal_inward(index) else {
                triangles_skipped += 1;
                continue;
            };
            let [v0, v1, _] = triangle.map(|i| vertices[i as usize]);
            // The contact does the projection of v1 − v0 onto the plane normal to n (twice
            // Gram–Schmidt) and the normalisation, exactly as for a grasp's given tangent.
            let cone = match Contact::try_new(v0, n, Some(sub(v1, v0))) {
                Ok(contact) => contact,
                // The edge is (to within 1e−6) along the computed normal: that normal is
                // rounding noise of a needle-thin triangle, which has no usable cone either.
                Err(GraspError::TangentParallelToNormal { .. }) => {
                    triangles_skipped += 1;
                    continue;
                }
                Err(e) => return Err(e.into()),
            };
            forces.clear();
            forces.push(n);
            // |f_j| ≥ 1 (its component along n is 1), so normalising never divides by zero.
            forces.extend(friction.edges(&cone).filter_map(normalize));
            for i in triangle {
                used[i as usize] = true;
                let r = sub(vertices[i as usize], c);
                for &e in &forces {
                    let tau = cross(r, e);
                    // Divided by ρ, as `Grasp`'s wrenches are, so a grasp contact at a corner
                    // with the same force reproduces the disturbance bit for bit.
                    let w = [e[0], e[1], e[2], tau[0] / rho, tau[1] / rho, tau[2] / rho];
                    if !w.iter().all(|x| x.is_finite()) {
                        return Err(OwsError::NonFinite {
                            index: disturbances.len(),
                        });
                    }
                    if seen.insert(w.map(|x| (x + 0.0).to_bits())) {
                        if disturbances.len() == max {
                            return Err(OwsError::TooManyDisturbances { max });
                        }
                        disturbances.push(w);
                    }
                }
            }
        }
        if disturbances.is_empty() {
            return Err(OwsError::Empty);
        }
        disturbances.shrink_to_fit();
        Ok(ObjectWrenchSpace {
            index: SupportIndex::new(&disturbances),
            disturbances,
            origin: SpaceOrigin::Mesh {
                centre_of_mass: c,
                centre_kind: mass.centre_kind,
                characteristic_length: rho,
                friction: friction.friction(),
                cone_edges: k,
            },
            vertices_without_normal: used.iter().filter(|&&u| !u).count(),
            triangles_skipped,
            reduced: false,
            ellipsoid: OnceLock::new(),
        })
    }

    /// A task wrench space: the given disturbance wrenches, in the grasps' torque units.
    ///
    /// # Errors
    /// [`OwsError::Empty`] for no disturbance; [`OwsError::NonFinite`] naming the first bad one;
    /// [`OwsError::AllZero`] when every disturbance is the zero wrench (zero disturbances among
    /// others are harmless: they constrain nothing); [`OwsError::TooManyDisturbances`] beyond
    /// [`MAX_DISTURBANCES`].
    pub fn from_disturbances(disturbances: Vec<[f64; 6]>) -> Result<Self, OwsError> {
        if disturbances.is_empty() {
            return Err(OwsError::Empty);
        }
        if disturbances.len() > MAX_DISTURBANCES {
            return Err(OwsError::TooManyDisturbances {
                max: MAX_DISTURBANCES,
            });
        }
        if let Some(index) = disturbances
            .iter()
            .position(|d| d.iter().any(|c| !c.is_finite()))
        {
            return Err(OwsError::NonFinite { index });
        }
        if disturbances.iter().flatten().all(|&c| c == 0.0) {
            return Err(OwsError::AllZero);
        }
        Ok(ObjectWrenchSpace {
            index: SupportIndex::new(&disturbances),
            disturbances,
            origin: SpaceOrigin::Given,
            vertices_without_normal: 0,
            triangles_skipped: 0,
            reduced: false,
            ellipsoid: OnceLock::new(),
        })
    }

    /// The disturbance wrenches.
    pub fn disturbances(&self) -> &[[f64; 6]] {
        &self.disturbances
    }

    /// The disturbances' support function (a ball tree), as the partial method queries it.
    pub fn support_index(&self) -> &SupportIndex<6> {
        &self.index
    }

    /// Number of disturbances.
    pub fn len(&self) -> usize {
        self.disturbances.len()
    }

    /// Always `false`: a space has at least one disturbance.
    pub fn is_empty(&self) -> bool {
        self.disturbances.is_empty()
    }

    /// Where the space came from (with the mesh's torque frame).
    pub fn origin(&self) -> &SpaceOrigin {
        &self.origin
    }

    /// Mesh vertices left out: those that are a corner of no usable (non-degenerate) triangle,
    /// so no disturbance acts there (0 for a given task wrench space).
    pub fn vertices_without_normal(&self) -> usize {
        self.vertices_without_normal
    }

    /// Mesh triangles left out because they have no inward normal (zero area), or one that is
    /// rounding noise (a needle whose first edge lies along it); 0 for a given task wrench space.
    pub fn triangles_skipped(&self) -> usize {
        self.triangles_skipped
    }

    /// Whether [`reduce_to_hull_vertices`](Self::reduce_to_hull_vertices) has run.
    pub fn is_reduced(&self) -> bool {
        self.reduced
    }

    /// The torque frame (reference point, scale) grasps must use, for a space built from a mesh.
    pub fn torque_frame(&self) -> Option<([f64; 3], f64)> {
        match self.origin {
            SpaceOrigin::Mesh {
                centre_of_mass,
                characteristic_length,
                ..
            } => Some((centre_of_mass, characteristic_length)),
            SpaceOrigin::Given => None,
        }
    }

    /// `grasp` rebuilt in this space's torque frame (unchanged for a given task wrench space).
    ///
    /// # Errors
    /// As [`Grasp::builder`]'s `build` (it cannot fail for a valid grasp and a valid frame).
    pub fn frame(&self, grasp: &Grasp) -> Result<Grasp, GraspError> {
        match self.torque_frame() {
            Some((c, rho)) => Grasp::builder(grasp.contacts().to_vec(), grasp.friction())
                .torque_reference(c)
                .torque_scale(rho)
                .build(),
            None => Ok(grasp.clone()),
        }
    }

    /// Keeps only the vertices of the disturbances' convex hull (the metric depends on nothing
    /// else: the gauge of the GWS is convex, so its maximum over the hull is at a vertex). Returns
    /// how many disturbances remain.
    ///
    /// Worth it where many disturbances are not extreme — flat faces, whose interior vertices
    /// share one normal — and expensive where they all are: the OWS of a smooth mesh has every
    /// point as a hull vertex and millions of facets (measured: 8,000 six-dimensional points gave
    /// 3.8 million facets, each one created and tested by the full hull). Nothing changes when the
    /// set spans fewer than six dimensions.
    ///
    /// # Errors
    /// [`HullError`] only for reasons other than a flat set (which is kept as is).
    pub fn reduce_to_hull_vertices(&mut self) -> Result<usize, HullError> {
        match Hull::try_new(&self.disturbances) {
            Ok(hull) => {
                let keep = hull.vertex_indices();
                self.disturbances = keep.iter().map(|&i| self.disturbances[i]).collect();
                self.index = SupportIndex::new(&self.disturbances);
                self.reduced = true;
                self.ellipsoid = OnceLock::new();
            }
            Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => {}
            Err(e) => return Err(e),
        }
        Ok(self.disturbances.len())
    }

    /// The minimum-volume ellipsoid centred at the origin enclosing every disturbance (Borst et
    /// al.'s approximation), computed on first use and cached.
    ///
    /// # Errors
    /// [`EllipsoidError`] when the disturbances span fewer than six dimensions.
    pub fn ellipsoid(&self) -> Result<&CentredEllipsoid<6>, EllipsoidError> {
        self.ellipsoid
            .get_or_init(|| {
                CentredEllipsoid::try_enclosing(&self.disturbances, ELLIPSOID_TOLERANCE)
            })
            .as_ref()
            .map_err(Clone::clone)
    }

    /// The space as JSON: `{"disturbances": [[6 numbers], …], "origin": {…}}`.
    pub fn to_json(&self) -> Value {
        let origin = match &self.origin {
            SpaceOrigin::Mesh {
                centre_of_mass,
                centre_kind,
                characteristic_length,
                friction,
                cone_edges,
            } => json!({
                "kind": "mesh",
                "centre_of_mass": centre_of_mass,
                "centre_kind": match centre_kind {
                    CentreKind::Volume => "volume",
                    CentreKind::SurfaceCentroid => "surface_centroid",
                },
                "characteristic_length": characteristic_length,
                "friction": friction,
                "cone_edges": cone_edges,
            }),
            SpaceOrigin::Given => json!({ "kind": "given" }),
        };
        json!({
            "disturbances": self.disturbances,
            "origin": origin,
            "vertices_without_normal": self.vertices_without_normal,
            "triangles_skipped": self.triangles_skipped,
            "reduced": self.reduced,
        })
    }

    /// Reads what [`to_json`](Self::to_json) wrote.
    ///
    /// # Errors
    /// [`OwsError::Json`] naming the first malformed field; the checks of
    /// [`from_disturbances`](Self::from_disturbances).
    pub fn from_json(value: &Value) -> Result<Self, OwsError> {
        let bad = |what: &str| OwsError::Json(what.to_string());
        let list = value
            .get("disturbances")
            .and_then(Value::as_array)
            .ok_or_else(|| bad("no \"disturbances\" array"))?;
        let mut disturbances = Vec::with_capacity(list.len());
        for (i, d) in list.iter().enumerate() {
            let row = d
                .as_array()
                .filter(|r| r.len() == 6)
                .ok_or_else(|| OwsError::Json(format!("disturbance {i} is not 6 numbers")))?;
            let mut w = [0.0; 6];
            for (c, x) in row.iter().enumerate() {
                w[c] = x
                    .as_f64()
                    .ok_or_else(|| OwsError::Json(format!("disturbance {i} is not 6 numbers")))?;
            }
            disturbances.push(w);
        }
        Self::from_json_parts(disturbances, value)
    }

    /// As [`from_json`](Self::from_json), with the disturbances given apart (as binary numbers,
    /// e.g. by a pickle or an array file) and the rest read from `value`, whose `"disturbances"`
    /// key, if any, is ignored: what [`to_json`](Self::to_json) writes without its
    /// `"disturbances"`.
    ///
    /// # Errors
    /// As [`from_json`](Self::from_json).
    pub fn from_json_parts(disturbances: Vec<[f64; 6]>, value: &Value) -> Result<Self, OwsError> {
        let bad = |what: &str| OwsError::Json(what.to_string());
        let mut space = Self::from_disturbances(disturbances)?;
        let origin = value.get("origin").ok_or_else(|| bad("no \"origin\""))?;
        let number = |key: &str| {
            origin
                .get(key)
                .and_then(Value::as_f64)
                .filter(|x| x.is_finite())
                .ok_or_else(|| OwsError::Json(format!("origin.{key} is not a finite number")))
        };
        space.origin = match origin.get("kind").and_then(Value::as_str) {
            Some("given") => SpaceOrigin::Given,
            Some("mesh") => {
                let c = origin
                    .get("centre_of_mass")
                    .and_then(Value::as_array)
                    .filter(|a| a.len() == 3)
                    .and_then(|a| {
                        let v: Vec<f64> = a.iter().filter_map(Value::as_f64).collect();
                        (v.len() == 3).then(|| [v[0], v[1], v[2]])
                    })
                    .ok_or_else(|| bad("origin.centre_of_mass is not 3 numbers"))?;
                let centre_kind = match origin.get("centre_kind").and_then(Value::as_str) {
                    Some("volume") => CentreKind::Volume,
                    Some("surface_centroid") => CentreKind::SurfaceCentroid,
                    _ => return Err(bad("origin.centre_kind is not volume|surface_centroid")),
                };
                let rho = number("characteristic_length")?;
                if rho <= 0.0 {
                    return Err(bad("origin.characteristic_length is not positive"));
                }
                SpaceOrigin::Mesh {
                    centre_of_mass: c,
                    centre_kind,
                    characteristic_length: rho,
                    friction: number("friction")?,
                    cone_edges: origin
                        .get("cone_edges")
                        .and_then(Value::as_u64)
                        .ok_or_else(|| bad("origin.cone_edges is not a count"))?
                        as usize,
                }
            }
            _ => return Err(bad("origin.kind is not mesh|given")),
        };
        space.vertices_without_normal = value
            .get("vertices_without_normal")
            .and_then(Value::as_u64)
            .unwrap_or(0) as usize;
        space.triangles_skipped = value
            .get("triangles_skipped")
            .and_then(Value::as_u64)
            .unwrap_or(0) as usize;
        space.reduced = value
            .get("reduced")
            .and_then(Value::as_bool)
            .unwrap_or(false);
        Ok(space)
    }
}

#[cfg(test)]
mod tests {
    use super::{ObjectWrenchSpace, OwsError};
    use crate::grasp::FrictionModel;
    use crate::mesh::Mesh;

    fn cube() -> Mesh {
        let vertices = (0..8)
            .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64])
            .map(|p| p.map(|x| 2.0 * x - 1.0))
            .collect();
        let faces = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let triangles = faces
            .iter()
            .flat_map(|&[a, b, c, d]| [[a, b, c], [a, c, d]])
            .collect();
        Mesh::try_new(vertices, triangles).unwrap()
    }

    /// The set is refused as soon as it would pass the limit, not after it is built.
    #[test]
    fn disturbances_are_bounded() {
        let friction = FrictionModel::try_new(0.5, 8).unwrap();
        let all = ObjectWrenchSpace::from_mesh(&cube(), friction)
            .unwrap()
            .len();
        assert!(all > 100);
        assert_eq!(
            ObjectWrenchSpace::from_mesh_at_most(&cube(), friction, all).map(|s| s.len()),
            Ok(all)
        );
        assert_eq!(
            ObjectWrenchSpace::from_mesh_at_most(&cube(), friction, all - 1).map(|s| s.len()),
            Err(OwsError::TooManyDisturbances { max: all - 1 })
        );
    }

    #[test]
    fn all_zero_disturbances_are_refused() {
        let zero = vec![[0.0; 6]; 3];
        assert_eq!(
            ObjectWrenchSpace::from_disturbances(zero).map(|s| s.len()),
            Err(OwsError::AllZero)
        );
        let mut some = vec![[0.0; 6]; 3];
        some[1][4] = 1e-300;
        assert_eq!(
            ObjectWrenchSpace::from_disturbances(some).map(|s| s.len()),
            Ok(3)
        );
    }
}
