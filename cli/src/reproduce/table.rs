//! A figure's data: named columns of equal length, written as CSV.
//!
//! Written by hand rather than with the `csv` crate: every cell is a number (Rust's shortest
//! round-trip decimal, so the file holds exactly the value plotted) or one of this module's own
//! labels (checked to need no quoting), so the format needs no escaping at all.

/// One column: numbers (NaN is written as an empty cell: not measured) or labels.
#[derive(Clone, Debug, PartialEq)]
pub enum Column {
    /// A numeric column.
    Numbers(String, Vec<f64>),
    /// A column of short labels (method or metric names).
    Labels(String, Vec<String>),
}

impl Column {
    /// The column's name (its CSV header).
    pub fn name(&self) -> &str {
        match self {
            Column::Numbers(name, _) | Column::Labels(name, _) => name,
        }
    }

    /// How many rows it holds.
    pub fn len(&self) -> usize {
        match self {
            Column::Numbers(_, v) => v.len(),
            Column::Labels(_, v) => v.len(),
        }
    }

    /// Whether it holds no rows.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    fn cell(&self, row: usize) -> String {
        match self {
            Column::Numbers(_, v) if v[row].is_nan() => String::new(),
            Column::Numbers(_, v) => format!("{}", v[row]),
            Column::Labels(_, v) => v[row].clone(),
        }
    }
}

/// A named table of columns of equal length.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// The file name without `.csv`.
    pub name: String,
    /// The columns, in order.
    pub columns: Vec<Column>,
}

impl Table {
    /// An empty table.
    pub fn new(name: impl Into<String>) -> Self {
        Table {
            name: name.into(),
            columns: Vec::new(),
        }
    }

    /// Adds a numeric column.
    ///
    /// # Panics
    /// If its length differs from the columns already there (a bug in the experiment).
    pub fn numbers(mut self, name: &str, values: Vec<f64>) -> Self {
        self.push(Column::Numbers(name.to_string(), values));
        self
    }

    /// Adds a label column.
    ///
    /// # Panics
    /// As [`numbers`](Self::numbers), or if a label holds a comma, a quote or a line break.
    pub fn labels(mut self, name: &str, values: Vec<String>) -> Self {
        assert!(
            values.iter().all(|v| !v.contains([',', '"', '\n', '\r'])),
            "labels are plain names"
        );
        self.push(Column::Labels(name.to_string(), values));
        self
    }

    fn push(&mut self, column: Column) {
        if let Some(first) = self.columns.first() {
            assert_eq!(first.len(), column.len(), "column {}", column.name());
        }
        self.columns.push(column);
    }

    /// Rows in the table.
    pub fn rows(&self) -> usize {
        self.columns.first().map_or(0, Column::len)
    }

    /// The numbers of column `name`.
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        self.columns.iter().find_map(|c| match c {
            Column::Numbers(n, v) if n == name => Some(v.as_slice()),
            _ => None,
        })
    }

    /// The labels of column `name`.
    pub fn label_column(&self, name: &str) -> Option<&[String]> {
        self.columns.iter().find_map(|c| match c {
            Column::Labels(n, v) if n == name => Some(v.as_slice()),
            _ => None,
        })
    }

    /// The table as CSV: a header line, then one line per row.
    ///
    /// ```
    /// use pqhull_cli::reproduce::Table;
    /// let t = Table::new("t")
    ///     .labels("method", vec!["a".into(), "b".into()])
    ///     .numbers("x", vec![0.1, f64::NAN]);
    /// assert_eq!(t.to_csv(), "method,x\na,0.1\nb,\n");
    /// ```
    pub fn to_csv(&self) -> String {
        let mut out = self
            .columns
            .iter()
            .map(Column::name)
            .collect::<Vec<_>>()
            .join(",");
        out.push('\n');
        for row in 0..self.rows() {
            let cells: Vec<String> = self.columns.iter().map(|c| c.cell(row)).collect();
            out.push_str(&cells.join(","));
            out.push('\n');
        }
        out
    }
}
