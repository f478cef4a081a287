//! [`MeshError`]: why a mesh could not be loaded, built or generated.

use std::fmt;
use std::io;
use std::path::PathBuf;

/// Why a [`Mesh`](super::Mesh) could not be loaded, built or generated.
///
/// Variants that can arise both from a file and from arrays given to
/// [`Mesh::try_new`](super::Mesh::try_new) carry `source_name: Option<String>`: the file (or the
/// name given to a `from_*_reader` function) when the mesh came from one, `None` otherwise. Vertex,
/// triangle and face indices are 0-based, counted in the order the input gives them.
#[derive(Debug)]
#[non_exhaustive]
pub enum MeshError {
    /// The file could not be opened or read.
    Io {
        /// The file.
        path: PathBuf,
        /// What the operating system said.
        source: io::Error,
    },
    /// The file name does not end in `.obj` or `.stl` (in any letter case).
    UnsupportedFormat {
        /// The file.
        path: PathBuf,
    },
    /// The file is not valid OBJ or STL.
    Parse {
        /// The file, or the name given to the reader function.
        source_name: String,
        /// What was wrong, and where when the parser says (an OBJ line number).
        message: String,
    },
    /// An OBJ face (or line element) that is not a triangle. Faces are never triangulated
    /// silently: a polygon's triangulation is a modelling decision.
    NotTriangle {
        /// The file, or the name given to the reader function.
        source_name: String,
        /// Index of the face among the file's `f` and `l` elements, in file order.
        face: usize,
        /// How many vertices it has.
        vertices: usize,
    },
    /// No vertices or no triangles.
    Empty {
        /// The file, if the mesh came from one.
        source_name: Option<String>,
        /// Vertices given.
        vertices: usize,
        /// Triangles given.
        triangles: usize,
    },
    /// A vertex with a NaN or infinite coordinate.
    NonFiniteVertex {
        /// The file, if the mesh came from one.
        source_name: Option<String>,
        /// Index of the vertex.
        vertex: usize,
        /// Its coordinates.
        coordinates: [f64; 3],
    },
    /// A triangle refers to a vertex that does not exist.
    IndexOutOfRange {
        /// The file, if the mesh came from one.
        source_name: Option<String>,
        /// Index of the triangle.
        triangle: usize,
        /// The offending vertex index.
        index: u32,
        /// The number of vertices.
        vertex_count: usize,
    },
    /// Every triangle is degenerate (a repeated vertex index, or three collinear corners): the
    /// surface has zero area, so it has no centroid, no normals and cannot be sampled.
    ZeroArea {
        /// The file, if the mesh came from one.
        source_name: Option<String>,
        /// Triangles given.
        triangles: usize,
    },
    /// More triangles than the `u32` handles of the surface index and the topology can name
    /// ([`MAX_TRIANGLES`](super::MAX_TRIANGLES)).
    TooManyTriangles {
        /// The file, if the mesh came from one.
        source_name: Option<String>,
        /// Triangles given.
        triangles: usize,
        /// The most accepted.
        max: usize,
    },
    /// A parameter of a generated shape ([`Mesh::cuboid`](super::Mesh::cuboid),
    /// [`Mesh::uv_sphere`](super::Mesh::uv_sphere)) is out of range.
    InvalidParameter {
        /// The parameter.
        name: &'static str,
        /// Its value, formatted.
        value: String,
        /// What it must be.
        expected: &'static str,
    },
}

/// `"mesh 'NAME'"` or `"mesh"`.
struct Subject<'a>(&'a Option<String>);

impl fmt::Display for Subject<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            Some(name) => write!(f, "mesh '{name}'"),
            None => f.write_str("mesh"),
        }
    }
}

impl fmt::Display for MeshError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MeshError::Io { path, source } => {
                write!(f, "cannot read mesh file '{}': {source}", path.display())
            }
            MeshError::UnsupportedFormat { path } => write!(
                f,
                "mesh file '{}': unsupported format (the name must end in .obj or .stl)",
                path.display()
            ),
            MeshError::Parse {
                source_name,
                message,
            } => write!(f, "mesh '{source_name}': {message}"),
            MeshError::NotTriangle {
                source_name,
                face,
                vertices,
            } => write!(
                f,
                "mesh '{source_name}': face {face} (0-based, counting `f` and `l` elements in file \
                 order) has {vertices} vertices; only triangles are supported (triangulate the \
                 mesh first)"
            ),
            MeshError::TooManyTriangles {
                source_name,
                triangles,
                max,
            } => write!(
                f,
                "{} has {triangles} triangles; at most {max} are supported",
                Subject(source_name)
            ),
            MeshError::Empty {
                source_name,
                vertices,
                triangles,
            } => write!(
                f,
                "{} is empty: {vertices} vertices and {triangles} triangles (at least one of \
                 each is needed)",
                Subject(source_name)
            ),
            MeshError::NonFiniteVertex {
                source_name,
                vertex,
                coordinates,
            } => write!(
                f,
                "{}: vertex {vertex} has a non-finite coordinate ({}, {}, {})",
                Subject(source_name),
                coordinates[0],
                coordinates[1],
                coordinates[2]
            ),
            MeshError::IndexOutOfRange {
                source_name,
                triangle,
                index,
                vertex_count,
            } => write!(
                f,
                "{}: triangle {triangle} refers to vertex {index}, but there are only \
                 {vertex_count} vertices",
                Subject(source_name)
            ),
            MeshError::ZeroArea {
                source_name,
                triangles,
            } => write!(
                f,
                "{}: all {triangles} triangles are degenerate (repeated or collinear corners), \
                 so the surface has zero area",
                Subject(source_name)
            ),
            MeshError::InvalidParameter {
                name,
                value,
                expected,
            } => write!(f, "invalid {name} = {value}: expected {expected}"),
        }
    }
}

impl std::error::Error for MeshError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            MeshError::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}
