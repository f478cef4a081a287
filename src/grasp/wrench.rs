//! Contact wrenches: the point sets behind Q1 (union) and Q∞ (Minkowski sum).

use super::Grasp;
use crate::geometry::vector::{add, cross, scale, sub};

impl Grasp {
    /// The k edge forces f_ij of contact `i`'s friction pyramid, j = 0, 1, …, k − 1:
    /// f_ij = n_i + μ (cos(2πj/k) t_i + sin(2πj/k) (n_i × t_i)). Allocates nothing.
    ///
    /// # Panics
    ///
    /// When `i` is not a contact index (`i ≥ m`).
    pub fn cone_edges(&self, i: usize) -> impl ExactSizeIterator<Item = [f64; 3]> + use<> {
        self.friction.edges(&self.contacts[i])
    }

    /// The number of wrenches in the union: k per hard contact, 2k per soft one (saturating at
    /// `usize::MAX`, which no real grasp reaches).
    pub fn wrench_count(&self) -> usize {
        (0..self.contacts.len()).fold(0usize, |n, i| {
            n.saturating_add(self.contact_wrench_count(i))
        })
    }

    /// The number of wrenches of contact `i`: k, or 2k for a soft contact.
    ///
    /// # Panics
    /// When `i ≥ m`.
    pub fn contact_wrench_count(&self, i: usize) -> usize {
        let k = self.friction.cone_edges();
        if self.contacts[i].is_soft() { 2 * k } else { k }
    }

    /// The union of all contact wrenches w_ij = [f_ij ; (p_i − c) × f_ij / ρ] — the Q1 point set —
    /// in contact-major order: for hard contacts, index i·k + j holds edge j of contact i. A soft
    /// contact (torsion γ, [`Contact::with_torsion`](super::Contact::with_torsion)) contributes
    /// 2k wrenches, [f_ij ; ((p_i − c) × f_ij + γ n_i) / ρ] for j = 0 … k − 1, then the same with
    /// −γ n_i.
    ///
    /// Allocates the result; in a loop over many grasps use [`Grasp::wrenches_into`] (or
    /// [`Grasp::contact_wrenches`]) with a reused buffer instead.
    pub fn wrenches(&self) -> Vec<[f64; 6]> {
        let mut out = Vec::with_capacity(self.wrench_count());
        self.wrenches_into(&mut out);
        out
    }

    /// [`Grasp::wrenches`] written into `out` (cleared first). Allocates only when `out`'s
    /// capacity is below m·k, so batch evaluation that reuses one buffer per worker does not
    /// allocate per grasp in steady state.
    pub fn wrenches_into(&self, out: &mut Vec<[f64; 6]>) {
        out.clear();
        out.reserve(self.wrench_count());
        for i in 0..self.contacts.len() {
            let start = out.len();
            out.resize(start + self.contact_wrench_count(i), [0.0; 6]);
            self.contact_wrenches(i, &mut out[start..]);
        }
    }

    /// The wrenches of contact `i` ([`contact_wrench_count`](Self::contact_wrench_count) of
    /// them, in [`Grasp::wrenches`]' order), written into `out`. Allocates nothing: the building
    /// block for the Q∞ Minkowski sum, whose support point is the sum of each contact's own.
    ///
    /// # Panics
    ///
    /// When `i ≥ m` or `out.len()` is not the contact's wrench count.
    pub fn contact_wrenches(&self, i: usize, out: &mut [[f64; 6]]) {
        let count = self.contact_wrench_count(i);
        assert_eq!(
            out.len(),
            count,
            "contact_wrenches: the buffer holds {} wrenches, contact {i} has {count}",
            out.len()
        );
        let r = self.lever_arm(i);
        let contact = &self.contacts[i];
        if contact.is_soft() {
            let k = self.friction.cone_edges();
            let twist = scale(contact.normal(), contact.torsion());
            let (plus, minus) = out.split_at_mut(k);
            for ((a, b), f) in plus.iter_mut().zip(minus).zip(self.cone_edges(i)) {
                let tau = cross(r, f);
                *a = self.wrench_with_torque(f, add(tau, twist));
                *b = self.wrench_with_torque(f, sub(tau, twist));
            }
        } else {
            for (slot, f) in out.iter_mut().zip(self.cone_edges(i)) {
                *slot = self.wrench(r, f);
            }
        }
    }

    /// The number of points of the Minkowski sum ⊕_i {w_i1 … w_ik} behind Q∞: k^m for hard
    /// contacts (a soft one's set has 2k wrenches), or `None` when it does not fit in a
    /// `usize`. The set itself is never materialised here. The same as
    /// [`minkowski_points(false)`](Self::minkowski_points).
    pub fn minkowski_count(&self) -> Option<usize> {
        self.minkowski_points(false)
    }

    /// p_i − c.
    fn lever_arm(&self, i: usize) -> [f64; 3] {
        sub(self.contacts[i].position(), self.torque_reference)
    }

    /// w = [f ; r × f / ρ] with r = p − c.
    pub(in crate::grasp) fn wrench(&self, r: [f64; 3], f: [f64; 3]) -> [f64; 6] {
        self.wrench_with_torque(f, cross(r, f))
    }

    /// w = [f ; τ / ρ].
    pub(in crate::grasp) fn wrench_with_torque(&self, f: [f64; 3], tau: [f64; 3]) -> [f64; 6] {
        let rho = self.torque_scale;
        [f[0], f[1], f[2], tau[0] / rho, tau[1] / rho, tau[2] / rho]
    }
}

#[cfg(test)]
mod tests {
    use crate::geometry::vector::{dot, norm};
    use crate::grasp::{Contact, FrictionModel, Grasp, GraspError};

    fn contact(p: [f64; 3], n: [f64; 3], t: Option<[f64; 3]>) -> Contact {
        Contact::try_new(p, n, t).unwrap()
    }

    /// Three contacts on the unit cube [−½, ½]³ with explicit tangents.
    fn cube_contacts() -> Vec<Contact> {
        vec![
            contact([-0.5, 0.1, 0.2], [1.0, 0.0, 0.0], Some([0.0, 1.0, 1.0])),
            contact([0.5, -0.2, 0.0], [-1.0, 0.0, 0.0], Some([0.0, 0.0, 1.0])),
            contact([0.1, 0.3, 0.5], [0.0, 0.1, -1.0], Some([1.0, 0.0, 0.0])),
        ]
    }

    fn force(w: &[f64; 6]) -> [f64; 3] {
        [w[0], w[1], w[2]]
    }

    fn torque(w: &[f64; 6]) -> [f64; 3] {
        [w[3], w[4], w[5]]
    }

    fn rotate(r: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
        [dot(r[0], v), dot(r[1], v), dot(r[2], v)]
    }

    /// Rotation by `angle` about the unit `axis` (Rodrigues).
    fn rotation(axis: [f64; 3], angle: f64) -> [[f64; 3]; 3] {
        let a = crate::geometry::vector::normalize(axis).unwrap();
        let (s, c) = angle.sin_cos();
        let [x, y, z] = a;
        let v = 1.0 - c;
        [
            [c + x * x * v, x * y * v - z * s, x * z * v + y * s],
            [y * x * v + z * s, c + y * y * v, y * z * v - x * s],
            [z * x * v - y * s, z * y * v + x * s, c + z * z * v],
        ]
    }

    #[test]
    fn counts_and_contact_major_order() {
        let k = 8;
        let fm = FrictionModel::try_new(0.4, k).unwrap();
        let g = Grasp::builder(cube_contacts(), fm).build().unwrap();
        assert_eq!(g.contact_count(), 3);
        assert_eq!(g.wrench_count(), 24);
        let all = g.wrenches();
        assert_eq!(all.len(), 24);
        let mut buf = vec![[f64::NAN; 6]; k];
        for i in 0..3 {
            g.contact_wrenches(i, &mut buf);
            assert_eq!(&all[i * k..(i + 1) * k], &buf[..]);
            for (j, f) in g.cone_edges(i).enumerate() {
                assert_eq!(force(&all[i * k + j]), f);
            }
        }
        // The reusable buffer path gives the same and keeps its allocation.
        let mut out = Vec::with_capacity(100);
        out.push([1.0; 6]);
        let ptr = out.as_ptr();
        g.wrenches_into(&mut out);
        assert_eq!(out, all);
        assert_eq!(out.as_ptr(), ptr);
        assert_eq!(g.minkowski_count(), Some(512));
    }

    #[test]
    fn minkowski_count_is_checked() {
        let c = contact([0.0; 3], [0.0, 0.0, 1.0], None);
        let fm = FrictionModel::try_new(0.5, 3).unwrap();
        assert_eq!(
            Grasp::builder(vec![c], fm)
                .build()
                .unwrap()
                .minkowski_count(),
            Some(3)
        );
        let g = Grasp::builder(vec![c; 41], fm).build().unwrap(); // 3^41 > 2^64
        assert_eq!(g.minkowski_count(), None);
        let fm = FrictionModel::try_new(0.5, 32).unwrap();
        let g = Grasp::builder(vec![c; 4], fm).build().unwrap();
        assert_eq!(g.minkowski_count(), Some(1 << 20));
    }

    #[test]
    fn contact_at_the_reference_point_has_zero_torque() {
        let p = [0.3, -0.7, 0.25];
        let c = contact(p, [1.0, 2.0, -0.5], None);
        let fm = FrictionModel::try_new(0.8, 16).unwrap();
        let g = Grasp::builder(vec![c], fm)
            .torque_reference(p)
            .torque_scale(0.3)
            .build()
            .unwrap();
        for w in g.wrenches() {
            assert_eq!(torque(&w), [0.0; 3]);
            assert!((dot(force(&w), c.normal()) - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn wrench_matches_the_formula() {
        let fm = FrictionModel::try_new(0.5, 6).unwrap();
        let cref = [0.1, 0.0, -0.2];
        let rho = 1.7;
        let g = Grasp::builder(cube_contacts(), fm)
            .torque_reference(cref)
            .torque_scale(rho)
            .build()
            .unwrap();
        let w = g.wrenches();
        for (i, c) in cube_contacts().iter().enumerate() {
            let r = crate::geometry::vector::sub(c.position(), cref);
            for (j, f) in g.cone_edges(i).enumerate() {
                let tau = crate::geometry::vector::cross(r, f);
                let got = torque(&w[i * 6 + j]);
                for a in 0..3 {
                    assert_eq!(got[a], tau[a] / rho);
                }
            }
        }
    }

    #[test]
    fn torque_scale_divides_torques() {
        let fm = FrictionModel::try_new(0.5, 8).unwrap();
        let c = [0.05, -0.1, 0.0];
        let base = Grasp::builder(cube_contacts(), fm)
            .torque_reference(c)
            .build()
            .unwrap()
            .wrenches();
        for rho in [0.25, 2.5, 1e-3, 1e3] {
            let g = Grasp::builder(cube_contacts(), fm)
                .torque_reference(c)
                .torque_scale(rho)
                .build()
                .unwrap();
            assert_eq!(g.torque_scale(), rho);
            for (w, w1) in g.wrenches().iter().zip(&base) {
                assert_eq!(force(w), force(w1));
                for a in 3..6 {
                    assert!((w[a] * rho - w1[a]).abs() <= 1e-15 * w1[a].abs().max(1.0));
                }
            }
        }
    }

    #[test]
    fn rigid_rotation_about_the_reference_rotates_wrenches() {
        let fm = FrictionModel::try_new(0.6, 12).unwrap();
        let c = [0.2, -0.1, 0.3];
        let rho = 0.9;
        let grasp = |contacts| {
            Grasp::builder(contacts, fm)
                .torque_reference(c)
                .torque_scale(rho)
                .build()
                .unwrap()
        };
        let before = grasp(cube_contacts()).wrenches();
        for (axis, angle) in [
            ([0.0, 0.0, 1.0], 0.7),
            ([1.0, -2.0, 0.5], 2.1),
            ([0.3, 0.3, 0.3], -1.2),
        ] {
            let r = rotation(axis, angle);
            let rotated: Vec<Contact> = cube_contacts()
                .iter()
                .map(|k| {
                    let rel = crate::geometry::vector::sub(k.position(), c);
                    let p = crate::geometry::vector::add(c, rotate(&r, rel));
                    contact(p, rotate(&r, k.normal()), Some(rotate(&r, k.tangent())))
                })
                .collect();
            let after = grasp(rotated).wrenches();
            assert_eq!(after.len(), before.len());
            for (w, w0) in after.iter().zip(&before) {
                let (f, t) = (force(w), torque(w));
                let (f0, t0) = (force(w0), torque(w0));
                assert!((norm(f) - norm(f0)).abs() < 1e-14);
                assert!((norm(t) - norm(t0)).abs() < 1e-14);
                let (rf, rt) = (rotate(&r, f0), rotate(&r, t0));
                for a in 0..3 {
                    assert!((f[a] - rf[a]).abs() < 1e-14, "force {f:?} vs {rf:?}");
                    assert!((t[a] - rt[a]).abs() < 1e-14, "torque {t:?} vs {rt:?}");
                }
            }
        }
    }

    #[test]
    fn every_grasp_error() {
        let fm = FrictionModel::try_new(0.5, 4).unwrap();
        assert_eq!(
            Grasp::builder(vec![], fm).build(),
            Err(GraspError::NoContacts)
        );
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let got = Grasp::builder(cube_contacts(), fm)
                .torque_reference([0.0, bad, 0.0])
                .build();
            assert_eq!(got, Err(GraspError::NonFiniteTorqueReference));
        }
        for bad in [0.0, -0.0, -1.0, f64::INFINITY] {
            let got = Grasp::builder(cube_contacts(), fm)
                .torque_scale(bad)
                .build();
            assert_eq!(
                got,
                Err(GraspError::InvalidTorqueScale { torque_scale: bad })
            );
        }
        let got = Grasp::builder(cube_contacts(), fm)
            .torque_scale(f64::NAN)
            .build();
        assert!(
            matches!(got, Err(GraspError::InvalidTorqueScale { torque_scale }) if torque_scale.is_nan())
        );
        // Defaults.
        let g = Grasp::builder(cube_contacts(), fm).build().unwrap();
        assert_eq!(g.torque_reference(), [0.0; 3]);
        assert_eq!(g.torque_scale(), 1.0);
        assert_eq!(g.friction(), fm);
        assert_eq!(g.contacts(), &cube_contacts()[..]);
    }

    #[test]
    fn contact_count_is_bounded() {
        use crate::grasp::MAX_CONTACTS;
        let fm = FrictionModel::try_new(0.5, 4).unwrap();
        let one = cube_contacts()[0];
        assert!(Grasp::builder(vec![one; MAX_CONTACTS], fm).build().is_ok());
        let got = Grasp::builder(vec![one; MAX_CONTACTS + 1], fm).build();
        assert_eq!(
            got,
            Err(GraspError::TooManyContacts {
                contacts: MAX_CONTACTS + 1,
                max: MAX_CONTACTS
            })
        );
        assert!(got.unwrap_err().to_string().contains("at most 256"));
    }

    #[test]
    #[should_panic(expected = "the buffer holds 3 wrenches")]
    fn contact_wrenches_rejects_a_wrong_buffer() {
        let fm = FrictionModel::try_new(0.5, 4).unwrap();
        let g = Grasp::builder(cube_contacts(), fm).build().unwrap();
        g.contact_wrenches(0, &mut [[0.0; 6]; 3]);
    }
}
