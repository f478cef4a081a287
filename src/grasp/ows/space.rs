//! The disturbance set: an object's wrench space from a mesh, or a given task wrench space.

use crate::grasp::ellipsoid::{CentredEllipsoid, EllipsoidError};
use crate::grasp::{Contact, FrictionModel, Grasp, GraspError};
use crate::hull::{Hull, HullError};
use crate::mesh::{CentreKind, Mesh};
use crate::strategy::SupportIndex;
use serde_json::{Value, json};
use std::fmt;
use std::sync::OnceLock;

/// The stopping tolerance of the approximate method's ellipsoid: its volume is within a factor
/// (1 + ε)^3 of the minimum ([`CentredEllipsoid::try_enclosing`]), and it contains every
/// disturbance exactly whatever ε.
pub const ELLIPSOID_TOLERANCE: f64 = crate::grasp::ellipsoid::DEFAULT_TOLERANCE;

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
        /// Cone edges per vertex.
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
            reduced: self.reduced,
            ellipsoid: OnceLock::new(),
        }
    }
}

/// Why an [`ObjectWrenchSpace`] could not be built or read.
#[derive(Clone, Debug, PartialEq)]
pub enum OwsError {
    /// No disturbance at all (an empty set, or a mesh none of whose vertices has a normal).
    Empty,
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
    /// The object wrench space of `mesh` with `friction`'s cones (see the
    /// [module docs](super) for the conventions).
    ///
    /// ```
    /// use pqhull::grasp::FrictionModel;
    /// use pqhull::grasp::ows::ObjectWrenchSpace;
    /// use pqhull::mesh::Mesh;
    ///
    /// let cube = Mesh::cuboid([0.5, 0.5, 0.5])?;
    /// let ows = ObjectWrenchSpace::from_mesh(&cube, FrictionModel::try_new(0.5, 4)?)?;
    /// assert_eq!(ows.len(), 8 * 4); // 8 vertices × 4 cone edges
    /// // Unit forces: the force part of every disturbance has length 1.
    /// let d = ows.disturbances()[0];
    /// assert!(((d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() - 1.0).abs() < 1e-15);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`OwsError::Empty`] when no vertex has a normal; [`OwsError::DegenerateMesh`] when ρ = 0.
    pub fn from_mesh(mesh: &Mesh, friction: FrictionModel) -> Result<Self, OwsError> {
        let mass = mesh.mass_properties();
        let rho = mass.characteristic_length;
        if !(rho > 0.0 && rho.is_finite()) {
            return Err(OwsError::DegenerateMesh);
        }
        let normals = mesh.vertex_normals_inward();
        let mut contacts = Vec::with_capacity(normals.len());
        for (&p, n) in mesh.vertices().iter().zip(&normals) {
            if let Some(n) = n {
                contacts.push(Contact::try_new(p, *n, None)?);
            }
        }
        let vertices_without_normal = normals.len() - contacts.len();
        if contacts.is_empty() {
            return Err(OwsError::Empty);
        }
        // The disturbances are exactly the wrenches a grasp with a contact at every vertex would
        // have, scaled to unit forces (every edge has length √(1 + μ²)).
        let all = Grasp::builder(contacts, friction)
            .torque_reference(mass.centre_of_mass)
            .torque_scale(rho)
            .build()?;
        let unit = 1.0 / (1.0 + friction.friction() * friction.friction()).sqrt();
        let disturbances: Vec<[f64; 6]> =
            all.wrenches().iter().map(|w| w.map(|c| c * unit)).collect();
        Ok(ObjectWrenchSpace {
            index: SupportIndex::new(&disturbances),
            disturbances,
            origin: SpaceOrigin::Mesh {
                centre_of_mass: mass.centre_of_mass,
                centre_kind: mass.centre_kind,
                characteristic_length: rho,
                friction: friction.friction(),
                cone_edges: friction.cone_edges(),
            },
            vertices_without_normal,
            reduced: false,
            ellipsoid: OnceLock::new(),
        })
    }

    /// A task wrench space: the given disturbance wrenches, in the grasps' torque units.
    ///
    /// # Errors
    /// [`OwsError::Empty`] for no disturbance; [`OwsError::NonFinite`] naming the first bad one.
    pub fn from_disturbances(disturbances: Vec<[f64; 6]>) -> Result<Self, OwsError> {
        if disturbances.is_empty() {
            return Err(OwsError::Empty);
        }
        if let Some(index) = disturbances
            .iter()
            .position(|d| d.iter().any(|c| !c.is_finite()))
        {
            return Err(OwsError::NonFinite { index });
        }
        Ok(ObjectWrenchSpace {
            index: SupportIndex::new(&disturbances),
            disturbances,
            origin: SpaceOrigin::Given,
            vertices_without_normal: 0,
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

    /// Mesh vertices left out because they have no normal.
    pub fn vertices_without_normal(&self) -> usize {
        self.vertices_without_normal
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
    /// point as a hull vertex and millions of facets (measured: 8,000 six-dimensional points,
    /// 3.8 million facets, 32 s). Nothing changes when the set spans fewer than six dimensions.
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
        space.reduced = value
            .get("reduced")
            .and_then(Value::as_bool)
            .unwrap_or(false);
        Ok(space)
    }
}
