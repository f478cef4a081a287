//! The shared hyperplanes of coplanar regions: one per region of two or more facets.
//!
//! Degenerate input (cube faces, lattices, the Minkowski sums of planar friction pyramids) makes
//! large regions of exactly coplanar facets, re-triangulated at every point added in their plane.
//! A new facet built on a ridge of a removed facet whose plane held the new point lies in that
//! same hyperplane (see ARCHITECTURE.md, "Coplanar regions"), so it takes the removed facet's
//! plane instead of computing its own: no cofactors to compute, and one exact-arithmetic cache
//! (built the first time the filter fails on the plane) for the whole region instead of one per
//! simplex.

use crate::predicates::FacetPlane;

/// A shared hyperplane: the plane through the vertices of the facet that founded the region.
#[derive(Clone, Debug)]
pub(in crate::hull) struct Plane<const D: usize> {
    /// The cached plane of `vertices` (internal coordinates).
    pub(in crate::hull) plane: FacetPlane<D>,
    /// The founding facet's vertices, in its oriented order: the points `plane` was built from,
    /// which its exact fallbacks must be given (they outlive the founder: points are never
    /// removed).
    pub(in crate::hull) vertices: [u32; D],
    /// Live facets using it; the slot is free at zero.
    users: u32,
    /// The last visit epoch (`Planes::begin_visit`) that met this plane.
    mark: u32,
}

/// No shared plane: the facet's own plane serves it (a region of one facet).
pub(in crate::hull) const NO_SLOT: u32 = u32::MAX;

/// The arena of shared planes, with a free list so that steady-state expansion allocates nothing.
/// A slot is made only when a second facet joins a region: general-position input, where no
/// region grows, never touches the arena.
#[derive(Clone, Debug, Default)]
pub(in crate::hull) struct Planes<const D: usize> {
    slots: Vec<Plane<D>>,
    free: Vec<u32>,
    /// The current visit epoch: a plane whose mark equals it was met in this visit.
    epoch: u32,
}

impl<const D: usize> Planes<D> {
    /// Forgets every plane (the slots' storage is kept).
    pub(in crate::hull) fn clear(&mut self) {
        self.free.clear();
        for (i, slot) in self.slots.iter_mut().enumerate().rev() {
            slot.users = 0;
            self.free.push(i as u32);
        }
    }

    /// A new plane with one user.
    pub(in crate::hull) fn add(&mut self, plane: FacetPlane<D>, vertices: [u32; D]) -> u32 {
        let fresh = Plane {
            plane,
            vertices,
            users: 1,
            mark: 0,
        };
        match self.free.pop() {
            Some(slot) => {
                self.slots[slot as usize] = fresh;
                slot
            }
            None => {
                self.slots.push(fresh);
                (self.slots.len() - 1) as u32
            }
        }
    }

    /// One more facet uses plane `slot`.
    pub(in crate::hull) fn share(&mut self, slot: u32) {
        self.slots[slot as usize].users += 1;
    }

    /// One facet fewer uses plane `slot`; the slot is reusable when none does.
    pub(in crate::hull) fn release(&mut self, slot: u32) {
        let entry = &mut self.slots[slot as usize];
        entry.users -= 1;
        if entry.users == 0 {
            self.free.push(slot);
        }
    }

    /// Starts a visit in which [`first_visit`](Self::first_visit) tells each plane's first
    /// meeting from later ones: the repartition's one candidate per region (for
    /// `Partition::NearestFirst`), found in one pass.
    pub(in crate::hull) fn begin_visit(&mut self) {
        self.epoch = self.epoch.wrapping_add(1);
        if self.epoch == 0 {
            // Wrapped: marks from 2^32 visits ago could match; clear them, and never use 0
            // (the mark of a fresh slot).
            for slot in &mut self.slots {
                slot.mark = 0;
            }
            self.epoch = 1;
        }
    }

    /// Whether this visit meets plane `slot` for the first time (marking it met).
    #[inline]
    pub(in crate::hull) fn first_visit(&mut self, slot: u32) -> bool {
        let entry = &mut self.slots[slot as usize];
        let first = entry.mark != self.epoch;
        entry.mark = self.epoch;
        first
    }

    /// Plane `slot`.
    #[inline]
    pub(in crate::hull) fn get(&self, slot: u32) -> &Plane<D> {
        &self.slots[slot as usize]
    }
}
