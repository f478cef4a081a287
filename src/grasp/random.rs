//! Seeded random grasps: on a box (the test object of the seed paper's GWS evaluation), on an
//! ellipsoid and on a mesh's surface.

use super::{Contact, FrictionModel, Grasp, GraspError};
use crate::geometry::Rng;
use crate::mesh::SurfaceSampler;

/// A grasp of `contacts` fingers drawn one after another by `finger`, with the torque reference
/// at the origin (the object's centre) and torque scale `rho`: the tail of the random objects'
/// generators.
///
/// # Panics
/// If `contacts` is 0 (the generators document it).
fn centred_grasp(
    rng: &mut Rng,
    contacts: usize,
    friction: FrictionModel,
    rho: f64,
    mut finger: impl FnMut(&mut Rng) -> Contact,
) -> Grasp {
    let fingers = (0..contacts).map(|_| finger(rng)).collect();
    Grasp::builder(fingers, friction)
        .torque_scale(rho)
        .build()
        .expect("a random grasp needs at least one contact")
}

impl Grasp {
    /// A random grasp with `contacts` fingers on the box [−h₀, h₀] × [−h₁, h₁] × [−h₂, h₂]: each
    /// on a uniformly chosen face, at a uniform point of it, pushing along the face's inward
    /// normal (default tangent). Torque reference: the box's centre; torque scale: its
    /// half-diagonal |h| (as GraspIt! does). Deterministic for a given `rng` state.
    ///
    /// ```
    /// use pqhull::grasp::{FrictionModel, Grasp};
    /// use pqhull::geometry::Rng;
    /// let mut rng = Rng::new(1);
    /// let g = Grasp::random_on_box(&mut rng, [0.5, 0.2, 0.1], 4, FrictionModel::try_new(0.5, 8)?);
    /// assert_eq!(g.contact_count(), 4);
    /// assert!(g.contacts().iter().all(|c| c.normal().iter().filter(|x| **x != 0.0).count() == 1));
    /// # Ok::<(), pqhull::grasp::GraspError>(())
    /// ```
    ///
    /// # Panics
    /// If `contacts` is 0 or a half extent is not finite and positive.
    pub fn random_on_box(
        rng: &mut Rng,
        half: [f64; 3],
        contacts: usize,
        friction: FrictionModel,
    ) -> Grasp {
        check_half_extents("random_on_box", half);
        let rho = half.iter().map(|h| h * h).sum::<f64>().sqrt();
        centred_grasp(rng, contacts, friction, rho, |rng| {
            let axis = rng.index(3);
            let sign = if rng.uniform() < 0.5 { -1.0 } else { 1.0 };
            let mut p: [f64; 3] = std::array::from_fn(|c| rng.uniform_in(-half[c], half[c]));
            p[axis] = sign * half[axis];
            let mut n = [0.0; 3];
            n[axis] = -sign;
            Contact::try_new(p, n, None).expect("an axis is a valid normal")
        })
    }

    /// A random grasp with `contacts` fingers on the ellipsoid x²/a² + y²/b² + z²/c² = 1 with
    /// semi-axes `semi = [a, b, c]`: each finger at the point (a·u₀, b·u₁, c·u₂) for a uniformly
    /// random unit vector u (not area-uniform: denser toward the short axes' ends), pushing along
    /// the surface's inward normal −(x/a², y/b², z/c²) normalised (default tangent). Unlike the
    /// box's, no two normals coincide, so the friction pyramids are in general position. Torque
    /// reference: the centre; torque scale: the largest semi-axis (the largest distance from
    /// the centre to the surface, as GraspIt! does).
    ///
    /// ```
    /// use pqhull::grasp::{FrictionModel, Grasp};
    /// use pqhull::geometry::Rng;
    /// let g = Grasp::random_on_ellipsoid(&mut Rng::new(1), [0.5, 0.2, 0.1], 4, FrictionModel::try_new(0.5, 8)?);
    /// for c in g.contacts() {
    ///     let [x, y, z] = c.position();
    ///     assert!((x * x / 0.25 + y * y / 0.04 + z * z / 0.01 - 1.0).abs() < 1e-12);
    ///     // Inward: the normal points back toward the centre.
    ///     assert!(x * c.normal()[0] + y * c.normal()[1] + z * c.normal()[2] < 0.0);
    /// }
    /// assert_eq!(g.torque_scale(), 0.5);
    /// # Ok::<(), pqhull::grasp::GraspError>(())
    /// ```
    ///
    /// # Panics
    /// If `contacts` is 0 or a semi-axis is not finite and positive.
    pub fn random_on_ellipsoid(
        rng: &mut Rng,
        semi: [f64; 3],
        contacts: usize,
        friction: FrictionModel,
    ) -> Grasp {
        check_half_extents("random_on_ellipsoid", semi);
        let rho = semi.iter().fold(0.0, |m: f64, &h| m.max(h));
        centred_grasp(rng, contacts, friction, rho, |rng| {
            let u = rng.unit_vector(3);
            let p: [f64; 3] = std::array::from_fn(|c| semi[c] * u[c]);
            let g: [f64; 3] = std::array::from_fn(|c| -p[c] / (semi[c] * semi[c]));
            let norm = g.iter().map(|x| x * x).sum::<f64>().sqrt();
            let n = g.map(|x| x / norm);
            Contact::try_new(p, n, None).expect("a unit normal off a point of the surface")
        })
    }

    /// A random grasp with `contacts` fingers (at most 6) on distinct faces of the box
    /// [−h₀, h₀] × [−h₁, h₁] × [−h₂, h₂]: the faces are a uniform choice of `contacts` of the six
    /// (a partial Fisher–Yates shuffle), each finger at a uniform point of its face, pushing along
    /// the face's inward normal n = −s·e_a (face x_a = s·h_a) with tangent e_(a+1 mod 3). Default
    /// torque frame: the box's centre and ρ = 1, so the torques are the plain p × f. This is the
    /// 6-D wrench set of `pqh compare`; unlike [`Grasp::random_on_box`], no two fingers share a
    /// face, so small grasps are often force closure.
    ///
    /// ```
    /// use pqhull::grasp::{FrictionModel, Grasp};
    /// use pqhull::geometry::Rng;
    /// let g = Grasp::random_on_distinct_faces(&mut Rng::new(1), [0.5; 3], 4, FrictionModel::try_new(0.5, 8)?);
    /// let mut faces: Vec<_> = g.contacts().iter().map(|c| c.normal().map(|x| x as i8)).collect();
    /// faces.sort();
    /// faces.dedup();
    /// assert_eq!(faces.len(), 4);
    /// assert_eq!(g.torque_scale(), 1.0);
    /// # Ok::<(), pqhull::grasp::GraspError>(())
    /// ```
    ///
    /// # Panics
    /// If `contacts` is 0 or more than 6, or a half extent is not finite and positive.
    pub fn random_on_distinct_faces(
        rng: &mut Rng,
        half: [f64; 3],
        contacts: usize,
        friction: FrictionModel,
    ) -> Grasp {
        assert!(
            (1..=6).contains(&contacts),
            "random_on_distinct_faces: 1 to 6 contacts (a box has six faces), got {contacts}"
        );
        check_half_extents("random_on_distinct_faces", half);
        // Face 2a is x_a = −h_a, face 2a + 1 is x_a = +h_a.
        let mut faces: [usize; 6] = [0, 1, 2, 3, 4, 5];
        for i in 0..contacts {
            let j = i + rng.index(6 - i);
            faces.swap(i, j);
        }
        let fingers = faces[..contacts]
            .iter()
            .map(|&face| {
                let (axis, sign) = (face / 2, if face % 2 == 0 { -1.0 } else { 1.0 });
                let mut p = [0.0; 3];
                for (c, x) in p.iter_mut().enumerate() {
                    *x = if c == axis {
                        half[c] * sign
                    } else {
                        rng.uniform_in(-half[c], half[c])
                    };
                }
                let mut n = [0.0; 3];
                n[axis] = -sign;
                let mut t = [0.0; 3];
                t[(axis + 1) % 3] = 1.0;
                Contact::try_new(p, n, Some(t)).expect("axes are a valid normal and tangent")
            })
            .collect();
        Grasp::builder(fingers, friction)
            .build()
            .expect("1 to 6 contacts")
    }

    /// A random grasp with `contacts` fingers at area-uniform points of a mesh's surface
    /// (`sampler`, built once per mesh), each pushing along its triangle's inward normal (default
    /// tangent), in the default torque frame; [`ObjectWrenchSpace::frame`] puts it in an object's
    /// frame. The points are `sampler`'s next `contacts` samples, so the same `rng` state gives
    /// the same grasp as [`Mesh::sample_surface`].
    ///
    /// [`ObjectWrenchSpace::frame`]: crate::grasp::ows::ObjectWrenchSpace::frame
    /// [`Mesh::sample_surface`]: crate::mesh::Mesh::sample_surface
    ///
    /// ```
    /// use pqhull::grasp::{FrictionModel, Grasp};
    /// use pqhull::mesh::{Mesh, SurfaceSampler};
    /// use pqhull::geometry::Rng;
    /// let cube = Mesh::cuboid([0.5, 0.5, 0.5])?;
    /// let sampler = SurfaceSampler::new(&cube);
    /// let friction = FrictionModel::try_new(0.5, 8)?;
    /// let g = Grasp::random_on_surface(&mut Rng::new(3), &sampler, 4, friction)?;
    /// assert_eq!(g.contact_count(), 4);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`GraspError`] when `contacts` is 0.
    pub fn random_on_surface(
        rng: &mut Rng,
        sampler: &SurfaceSampler,
        contacts: usize,
        friction: FrictionModel,
    ) -> Result<Grasp, GraspError> {
        let fingers = (0..contacts)
            .map(|_| {
                let s = sampler.sample(rng);
                Contact::try_new(s.position, s.inward_normal, None)
            })
            .collect::<Result<Vec<_>, _>>()?;
        Grasp::builder(fingers, friction).build()
    }
}

/// Panics unless every half extent of a box is finite and positive (the generators' `# Panics`).
fn check_half_extents(generator: &str, half: [f64; 3]) {
    assert!(
        half.iter().all(|h| h.is_finite() && *h > 0.0),
        "{generator}: half extents must be finite and positive, got {half:?}"
    );
}
