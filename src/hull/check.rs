//! The public validator: every invariant the engine promises, checked from scratch.

use super::facet::FacetId;
use super::{Hull, InvariantViolation, NO_FLAT};
use crate::geometry::vector::dot;
use crate::predicates::{Sign, orientation};

impl<const D: usize> Hull<D> {
    /// Checks every invariant of the hull, exactly where it can be:
    ///
    /// * live facets have live neighbours, links are symmetric, and neighbours across the ridge
    ///   opposite vertex `i` share exactly the other D − 1 vertices;
    /// * each facet's unit normal and offset match its vertices (to a relative 1e−9 of the point
    ///   set's extent — the only floating-point check; the exact plane *is* the vertices'); for a
    ///   facet whose normal is not [precise](super::Facet::normal_is_precise), the exact normal
    ///   [`Hull::refine_normals`](crate::Hull::refine_normals) would install (plus a few units of
    ///   the smallest subnormal, the rounding of underflowing products);
    /// * every input point lies weakly inside every live facet (exact predicate), except the points
    ///   in outside sets, which must lie strictly beyond their own facet (partial hulls);
    /// * a facet that shares its coplanar region's plane has its vertices exactly on it and the
    ///   same orientation;
    /// * every point of a declared affine flat that a facet is taken to contain (see the
    ///   engine's flat hints, used for friction pyramids) lies exactly on the facet's plane;
    /// * the arena's live count matches.
    ///
    /// Cost: one exact predicate per (point, facet) pair, so use it in tests, not in hot loops.
    ///
    /// # Errors
    /// The first violation found, naming the facets or points involved.
    pub fn check(&self) -> Result<(), InvariantViolation> {
        let fail = |message: String| Err(InvariantViolation { message });
        let live: Vec<FacetId> = self.facets().map(|(id, _)| id).collect();
        if live.len() != self.live {
            return fail(format!(
                "{} live facets, counter says {}",
                live.len(),
                self.live
            ));
        }
        let extent = self.extent();
        // The relative tolerance, plus what underflow adds: each product or sum below the normal
        // range errs by up to half the smallest subnormal, which for subnormal input is more
        // than 1e−9 of its extent (that tolerance would round to zero).
        let tolerance = 1e-9 * extent + (4 * D) as f64 * f64::from_bits(1);
        for &id in &live {
            let f = self.facet(id);
            for i in 0..D {
                let n = f.neighbors[i];
                let Some(nf) = self.facets.get(n.index()).filter(|nf| nf.alive) else {
                    return fail(format!("facet {} has dead neighbour {} at {i}", id.0, n.0));
                };
                let Some(back) = nf.neighbors.iter().position(|&b| b == id) else {
                    return fail(format!("facet {} → {} is not symmetric", id.0, n.0));
                };
                let shared = f.vertices.iter().enumerate().filter(|&(k, _)| k != i);
                for (_, v) in shared {
                    if !nf.vertices.contains(v) {
                        return fail(format!(
                            "facets {} and {} are neighbours but do not share vertex {v}",
                            id.0, n.0
                        ));
                    }
                }
                if nf.vertices.contains(&f.vertices[i]) || f.vertices.contains(&nf.vertices[back]) {
                    return fail(format!("facets {} and {} share all vertices", id.0, n.0));
                }
            }
            // A facet that shares its region's plane lies in it exactly and faces the same way
            // (checked with the exact predicate on both vertex sets, not through the cache).
            let (_, shared) = self.exact_plane_of(id);
            if *shared != f.vertices {
                let plane = self.coords(shared);
                for &v in &f.vertices {
                    if orientation(&plane, &self.points[v as usize]) != Sign::Zero {
                        return fail(format!(
                            "vertex {v} of facet {} is off the region plane it shares",
                            id.0
                        ));
                    }
                }
                let own = orientation(&self.coords(&f.vertices), &self.interior);
                if own == Sign::Zero || own != orientation(&plane, &self.interior) {
                    return fail(format!(
                        "facet {} and the region plane it shares face different ways",
                        id.0
                    ));
                }
            }
            // A thin facet's floating-point normal is only a hint (see `Facet::normal`): check the
            // exact one, which is what `refine_normals` installs.
            let (normal, offset) = if f.precise {
                (f.normal, f.offset)
            } else {
                let exact = self.exact_normal(id);
                let offset = dot(exact, self.point(f.vertices[0] as usize));
                (exact, offset)
            };
            let length = dot(normal, normal).sqrt();
            if (length - 1.0).abs() > 1e-9 {
                return fail(format!("facet {} normal has length {length}", id.0));
            }
            for &v in &f.vertices {
                let gap = dot(normal, self.point(v as usize)) - offset;
                if gap.abs() > tolerance {
                    return fail(format!("vertex {v} is {gap} off facet {}'s plane", id.0));
                }
            }
        }
        let mut owner = vec![None; self.points.len()];
        for &id in &live {
            for &p in &self.facet(id).outside {
                if owner[p as usize].replace(id).is_some() {
                    return fail(format!("point {p} is in two outside sets"));
                }
                if self.side(id, &self.points[p as usize]) != Sign::Positive {
                    return fail(format!(
                        "point {p} is in facet {}'s outside set but not beyond it",
                        id.0
                    ));
                }
            }
        }
        // The flat hints are trusted by the engine; here they are checked with the exact
        // predicate alone.
        for &id in &live {
            for &flat in self.facet(id).flats.iter().filter(|&&f| f != NO_FLAT) {
                let members = (0..self.flat_of.len()).filter(|&p| self.flat_of[p] == flat);
                for p in members {
                    if self.side(id, &self.points[p]) != Sign::Zero {
                        return fail(format!(
                            "point {p} of declared flat {flat} is off facet {}, which is taken \
                             to contain the flat",
                            id.0
                        ));
                    }
                }
            }
        }
        for (p, point) in self.points.iter().enumerate() {
            // A repeated point stands or falls with its first copy, checked in its own turn.
            if owner[p].is_some() || self.is_repeat(p) {
                continue;
            }
            for &id in &live {
                // A facet's own vertices lie on it by construction.
                if self.facet(id).vertices.contains(&(p as u32)) {
                    continue;
                }
                if self.side(id, point) == Sign::Positive {
                    return fail(format!(
                        "point {p} lies beyond facet {} but is in no outside set",
                        id.0
                    ));
                }
            }
        }
        Ok(())
    }

    /// Largest absolute coordinate of the input, in the caller's units.
    fn extent(&self) -> f64 {
        let max = self
            .points
            .iter()
            .flat_map(|p| p.iter())
            .fold(0.0f64, |m, x| m.max(x.abs()));
        max / self.scale
    }
}
