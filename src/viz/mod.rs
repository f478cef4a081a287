//! Visual debugging: recorded traces of a strategy's run and their SVG / HTML renderings.
