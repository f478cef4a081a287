//! Qhull baseline (feature `qhull`). STUB: owned by the benchmark work.
