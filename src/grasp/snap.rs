//! Wrenches snapped to a grid on which the friction pyramids are exactly planar.
//!
//! Contact i's wrenches are w_ij = u_i + cos θ_j · v_i + sin θ_j · s_i with u_i = A_i n_i,
//! v_i = μ A_i t_i, s_i = μ A_i (n_i × t_i) and A_i f = [f ; (p_i − c) × f / ρ]: all k of them lie in
//! one 2-D plane of wrench space. Computed naively in floating point they do not, quite, and an
//! exact hull then sees thousands of sliver facets that exist only in the rounding (and spends
//! its time in exact arithmetic deciding them). Snapping u, v, s to a grid of 2^−24 of each
//! coordinate's largest magnitude, and cos θ, sin θ to 2^−24, makes every product and sum below
//! exact in `f64` (24 + 25 bits per product, three terms, < 2^50 grid units), so the snapped
//! wrenches are *exactly* u + cos·v + sin·s, exactly coplanar per contact, and any sum of one
//! wrench per contact (the Q∞ Minkowski points) is exact too for up to 10 contacts
//! (< 3m·2^48 < 2^53 units). The change is below 2^−24 ≈ 6·10^−8 relative to the largest
//! coordinate — far below the error of the k-edge friction pyramid itself.
//!
//! Identical contacts (equal position, normal and tangent, hence equal wrenches) are kept once,
//! with their multiplicity: a repeated contact adds nothing to the Q1 union, and r copies of a
//! convex set C sum to r·C, so the Q∞ Minkowski sum needs each distinct contact once, scaled by
//! its multiplicity. Generated grasps repeat contacts often, and the sum's tied tuples otherwise
//! grow like (ties)^r.

use super::Grasp;
use crate::geometry::vector::{add, scale as scaled_by, sub};
use crate::predicates::times_power_of_two;
use std::f64::consts::PI;

/// Bits kept by the snapping (see the module docs for why 24).
const BITS: i32 = 24;

/// The finest grid: its products by the angles' grid `2^−BITS` are multiples of `2^−1074`.
const MIN_GRID_EXPONENT: i32 = -1074 + BITS;

/// The snapped generators of every pyramid: `[u, v, s]` per pyramid, and the snapped (cos, sin)
/// of every edge angle. A hard contact is one pyramid; a soft contact (torsion γ) two, with
/// u ± [0; γ n / ρ] and the same v, s: each exactly planar. "Contact" below means a distinct one
/// (see the module docs); for a grasp of hard contacts, pyramid i is contact i.
#[derive(Clone, Debug, Default)]
pub(in crate::grasp) struct SnappedCones {
    pub(in crate::grasp) generators: Vec<[[f64; 6]; 3]>,
    /// Per contact, its first pyramid; one more entry, the pyramid count, closes the last.
    pyramid_start: Vec<usize>,
    pub(in crate::grasp) angles: Vec<(f64, f64)>,
    /// The caller's wrenches, as [`Grasp::wrenches`] computes them (contact-major, each distinct
    /// contact once): the points every reported value is certified on.
    pub(in crate::grasp) raw: Vec<[f64; 6]>,
    /// Per contact: an upper bound on the distance between a raw wrench and its snapped one.
    pub(in crate::grasp) delta: Vec<f64>,
    /// Per contact: how many of the grasp's contacts it stands for (at least 1).
    pub(in crate::grasp) multiplicity: Vec<u32>,
    /// Per contact of the grasp: the distinct contact standing for it.
    pub(in crate::grasp) representative: Vec<u32>,
    /// Per contact: its index in the grasp (the first of its copies).
    first: Vec<usize>,
}

fn snap(x: f64, grid: f64) -> f64 {
    (x / grid).round() * grid
}

impl SnappedCones {
    /// Recomputes the generators for `grasp`, reusing this value's buffers.
    pub(in crate::grasp) fn fill(&mut self, grasp: &Grasp) {
        let mu = grasp.friction.friction();
        let k = grasp.friction.cone_edges();
        self.merge_repeats(grasp);
        self.generators.clear();
        self.pyramid_start.clear();
        for contact in self.first.iter().map(|&i| &grasp.contacts[i]) {
            self.pyramid_start.push(self.generators.len());
            let r = sub(contact.position(), grasp.torque_reference);
            let scaled = |v: [f64; 3]| v.map(|x| x * mu);
            let u = grasp.wrench(r, contact.normal());
            let v = grasp.wrench(r, scaled(contact.tangent()));
            let s = grasp.wrench(r, scaled(contact.bitangent()));
            if contact.is_soft() {
                let twist = grasp
                    .wrench_with_torque([0.0; 3], scaled_by(contact.normal(), contact.torsion()));
                self.generators.push([add(u, twist), v, s]);
                self.generators.push([sub(u, twist), v, s]);
            } else {
                self.generators.push([u, v, s]);
            }
        }
        self.pyramid_start.push(self.generators.len());
        let mut grid = [1.0f64; 6];
        for (c, g) in grid.iter_mut().enumerate() {
            let largest = self
                .generators
                .iter()
                .flat_map(|generator| generator.iter().map(|w| w[c].abs()))
                .fold(0.0f64, f64::max);
            if largest > 0.0 {
                // 2^e > largest, so snapped values are integers below 2^24 in units of the grid.
                // The grid is at least 2^(−1074 + 24), so that the products by the angles (in
                // units of 2^−24) stay multiples of the smallest subnormal: exact, even in a
                // column of subnormal torques (a contact at y = 1e−310). There the snapped values
                // are below 2^24 units all the more. (`powi` is not used: 2^−1053 by it is 0.)
                let e = largest.log2().floor() as i32 + 1;
                *g = times_power_of_two(1.0, (e - BITS).max(MIN_GRID_EXPONENT));
            }
        }
        for generator in &mut self.generators {
            for w in generator.iter_mut() {
                for (x, &g) in w.iter_mut().zip(&grid) {
                    *x = snap(*x, g);
                }
            }
        }
        let unit = 2f64.powi(-BITS);
        self.angles.clear();
        self.angles.extend((0..k).map(|j| {
            let (sin, cos) = (2.0 * PI * j as f64 / k as f64).sin_cos();
            (snap(cos, unit), snap(sin, unit))
        }));
        self.raw.clear();
        self.raw.resize(self.generators.len() * k, [0.0; 6]);
        for (c, &i) in self.first.iter().enumerate() {
            let out = &mut self.raw[self.pyramid_start[c] * k..self.pyramid_start[c + 1] * k];
            grasp.contact_wrenches(i, out);
        }
        self.delta.clear();
        for i in 0..self.generators.len() {
            let largest = (0..k)
                .map(|j| {
                    let (raw, snapped) = (self.raw[i * k + j], self.wrench(i, j));
                    raw.iter()
                        .zip(&snapped)
                        .map(|(a, b)| (a - b) * (a - b))
                        .sum::<f64>()
                        .sqrt()
                })
                .fold(0.0, f64::max);
            // The differences, squares and root round by a few ulps: 1e−15 relative covers them.
            self.delta.push(largest * (1.0 + 1e-15));
        }
    }

    /// Divides every wrench (snapped generators, raw wrenches, δ) by the power of two `unit`:
    /// exact, so the snapped wrenches stay exactly planar and their sums exact.
    pub(in crate::grasp) fn rescale(&mut self, unit: super::quality::WrenchUnit) {
        if unit.0 == 0 {
            return;
        }
        for generator in &mut self.generators {
            for w in generator.iter_mut() {
                *w = unit.apply(*w);
            }
        }
        for w in &mut self.raw {
            *w = unit.apply(*w);
        }
        for d in &mut self.delta {
            // Rounded up: δ must stay an upper bound.
            *d = unit.down(*d) * (1.0 + 1e-15) + f64::from_bits(1);
        }
    }

    /// Groups the grasp's contacts into distinct ones (quadratic in m ≤ 256, with an early exit
    /// per comparison: at most 32,640 comparisons, negligible against a hull of the m·k wrenches).
    fn merge_repeats(&mut self, grasp: &Grasp) {
        self.first.clear();
        self.multiplicity.clear();
        self.representative.clear();
        for (i, contact) in grasp.contacts.iter().enumerate() {
            let found = self
                .first
                .iter()
                .position(|&f| grasp.contacts[f] == *contact);
            let d = found.unwrap_or_else(|| {
                self.first.push(i);
                self.multiplicity.push(0);
                self.first.len() - 1
            });
            self.multiplicity[d] += 1;
            self.representative
                .push(u32::try_from(d).expect("at most MAX_CONTACTS contacts"));
        }
    }

    /// The number of pyramids: the distinct contacts, a soft one counting twice.
    pub(in crate::grasp) fn contacts(&self) -> usize {
        self.generators.len()
    }

    /// The number of distinct contacts (the summands of the Q∞ Minkowski sum).
    pub(in crate::grasp) fn distinct_contacts(&self) -> usize {
        self.multiplicity.len()
    }

    /// The pyramids of distinct contact `c`: one for a hard contact, two for a soft one.
    pub(in crate::grasp) fn pyramids_of(&self, c: usize) -> std::ops::Range<usize> {
        self.pyramid_start[c]..self.pyramid_start[c + 1]
    }

    /// The number of cone edges per contact.
    pub(in crate::grasp) fn edges(&self) -> usize {
        self.angles.len()
    }

    /// Wrench j of contact i: u + cos·v + sin·s, exact in `f64`.
    pub(in crate::grasp) fn wrench(&self, i: usize, j: usize) -> [f64; 6] {
        let [u, v, s] = &self.generators[i];
        let (cos, sin) = self.angles[j];
        std::array::from_fn(|c| u[c] + cos * v[c] + sin * s[c])
    }

    /// Whether every generator and raw wrench is finite (a tiny torque scale can overflow).
    pub(in crate::grasp) fn is_finite(&self) -> bool {
        self.generators
            .iter()
            .flatten()
            .flatten()
            .chain(self.raw.iter().flatten())
            .all(|x| x.is_finite())
            && self.delta.iter().all(|d| d.is_finite())
    }
}

impl Grasp {
    /// The Q1 wrench set as the metrics evaluate it: [`Grasp::wrenches`] snapped to a grid on
    /// which each contact's friction pyramid is exactly planar (relative change below 6·10⁻⁸ of
    /// the largest coordinate; see the [quality module](crate::grasp::quality)). Contact-major,
    /// written into `out` (cleared first).
    pub fn snapped_wrenches_into(&self, out: &mut Vec<[f64; 6]>) {
        let mut cones = SnappedCones::default();
        cones.fill(self);
        out.clear();
        for &d in &cones.representative {
            for p in cones.pyramids_of(d as usize) {
                out.extend((0..cones.edges()).map(|j| cones.wrench(p, j)));
            }
        }
    }
}

/// The union of the snapped wrenches, contact-major, each distinct contact once.
pub(in crate::grasp) fn snapped_union(cones: &SnappedCones, out: &mut Vec<[f64; 6]>) {
    out.clear();
    for i in 0..cones.generators.len() {
        out.extend((0..cones.angles.len()).map(|j| cones.wrench(i, j)));
    }
}

/// The contact of every wrench of [`snapped_union`] (`contacts` pyramids of `edges` wrenches):
/// the flats to declare to the hull engine, each pyramid lying exactly in one 2-D affine plane
/// (see the module docs).
pub(in crate::grasp) fn pyramid_labels(contacts: usize, edges: usize, out: &mut Vec<u32>) {
    out.clear();
    out.extend((0..contacts as u32).flat_map(|i| std::iter::repeat_n(i, edges)));
}

#[cfg(test)]
mod tests {
    use super::pyramid_labels;
    use crate::geometry::Rng;
    use crate::grasp::{Contact, FrictionModel, Grasp};
    use crate::{ClosestToOrigin, FarthestPoint, Hull, HullError};

    fn grasp(k: usize) -> Grasp {
        let contacts = vec![
            Contact::try_new([0.31, -0.2, 0.17], [-0.3, 1.0, 0.2], None).unwrap(),
            Contact::try_new([-0.4, 0.25, -0.1], [1.0, -0.1, 0.3], None).unwrap(),
        ];
        Grasp::builder(contacts, FrictionModel::try_new(0.7, k).unwrap())
            .torque_reference([0.01, 0.02, -0.03])
            .torque_scale(0.6)
            .build()
            .unwrap()
    }

    #[test]
    fn snapped_wrenches_are_close_and_exactly_planar_per_contact() {
        let g = grasp(16);
        let raw = g.wrenches();
        let mut snapped = Vec::new();
        g.snapped_wrenches_into(&mut snapped);
        assert_eq!(raw.len(), snapped.len());
        let largest = raw.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
        for (a, b) in raw.iter().zip(&snapped) {
            for c in 0..6 {
                assert!((a[c] - b[c]).abs() <= 1e-6 * largest, "{a:?} vs {b:?}");
            }
        }
        // One contact's 16 wrenches span exactly a 2-flat (exact rank), where the raw ones,
        // rounded independently, span 6-D.
        let planar = Hull::try_new(&snapped[..16]).unwrap_err();
        assert_eq!(
            planar,
            HullError::AffinelyDependent {
                rank: 2,
                dimension: 6
            }
        );
        let raw_rank = match Hull::try_new(&raw[..16]) {
            Ok(_) => 6,
            Err(HullError::AffinelyDependent { rank, .. }) => rank,
            Err(e) => panic!("{e}"),
        };
        assert!(raw_rank > 2, "raw rank {raw_rank}");
    }

    /// A grasp with `m` contacts at random points with random normals and tangents.
    fn random_grasp(rng: &mut Rng, m: usize, k: usize) -> Grasp {
        let vector = |rng: &mut Rng| std::array::from_fn(|_| rng.uniform_in(-1.0, 1.0));
        let contacts = (0..m)
            .map(|_| {
                let position: [f64; 3] = vector(rng);
                let normal: [f64; 3] = vector(rng);
                let tangent = (rng.uniform() < 0.5).then(|| vector(rng));
                Contact::try_new(position, normal, tangent)
                    .or_else(|_| Contact::try_new(position, normal, None))
                    .unwrap()
            })
            .collect();
        Grasp::builder(
            contacts,
            FrictionModel::try_new(rng.uniform_in(0.2, 1.0), k).unwrap(),
        )
        .torque_scale(rng.uniform_in(0.3, 2.0))
        .build()
        .unwrap()
    }

    /// Declaring the pyramids as flats changes no hull, and the claim holds exactly: `check`
    /// verifies every point of every flat a facet is taken to contain with the exact predicate.
    #[test]
    fn declared_pyramids_hold_exactly_and_change_no_hull() {
        let mut rng = Rng::new(42);
        let mut hinted = Hull::<6>::empty();
        let mut flats = Vec::new();
        let mut wrenches = Vec::new();
        let mut contains_a_flat = 0;
        for case in 0..60 {
            let (m, k) = (2 + case % 4, 3 + rng.index(10));
            let grasp = random_grasp(&mut rng, m, k);
            grasp.snapped_wrenches_into(&mut wrenches);
            pyramid_labels(m, k, &mut flats);
            let plain = match Hull::try_new(&wrenches) {
                Ok(hull) => hull,
                Err(HullError::AffinelyDependent { .. } | HullError::TooFewPoints { .. }) => {
                    continue;
                }
                Err(e) => panic!("case {case}: {e}"),
            };
            // The checked entry point: the snapped pyramids pass the exact rank test.
            hinted
                .rebuild_with_flats(&wrenches, &flats, 2, FarthestPoint::new())
                .unwrap();
            hinted
                .check()
                .unwrap_or_else(|e| panic!("case {case}: {e}"));
            let facets = |hull: &Hull<6>| {
                let mut all: Vec<[usize; 6]> = hull
                    .facets()
                    .map(|(_, f)| {
                        let mut v = f.vertices();
                        v.sort_unstable();
                        v
                    })
                    .collect();
                all.sort_unstable();
                all
            };
            assert_eq!(facets(&hinted), facets(&plain), "case {case}");
            contains_a_flat += hinted
                .facets()
                .filter(|(_, f)| f.contained_flats().next().is_some())
                .count();
            // The partial strategy reaches the same answer, bit for bit.
            let a = hinted
                .rebuild_with_trusted_flats(&wrenches, &flats, 2, ClosestToOrigin::new())
                .unwrap();
            let (_, b) = Hull::try_with_strategy(&wrenches, ClosestToOrigin::new()).unwrap();
            assert_eq!(a.signed_distance, b.signed_distance, "case {case}");
            assert_eq!(
                a.closest_facet_vertices, b.closest_facet_vertices,
                "case {case}"
            );
        }
        assert!(
            contains_a_flat > 100,
            "{contains_a_flat} facets contain a pyramid"
        );
    }
}
