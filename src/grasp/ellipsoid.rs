//! Minimum-volume enclosing ellipsoids centred at the origin (Borst et al.'s OWS approximation).
