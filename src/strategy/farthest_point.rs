//! Full QuickHull.
use super::{Step, Strategy};
use crate::hull::Hull;

/// Plain QuickHull to completion: the full hull.
#[derive(Clone, Debug, Default)]
pub struct FarthestPoint {
    _private: (),
}

impl FarthestPoint {
    /// A new full-hull strategy.
    pub fn new() -> Self {
        Self::default()
    }
}

impl<const D: usize> Strategy<D> for FarthestPoint {
    type Output = ();
    fn start(&mut self, _hull: &Hull<D>) {}
    fn step(&mut self, _hull: &mut Hull<D>) -> Step {
        todo!()
    }
    fn finish(self, _hull: &Hull<D>) -> Self::Output {}
}
