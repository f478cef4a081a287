//! Loading meshes from Wavefront OBJ (via `tobj`) and STL (via `stl_io`) files.

use std::collections::HashMap;
use std::fs::File;
use std::io::{self, BufRead, BufReader, Read, Seek};
use std::path::Path;

use super::{Mesh, MeshError};

impl Mesh {
    /// Loads a mesh from an `.obj` or `.stl` file (the extension decides, in any letter case).
    ///
    /// See [`Mesh::from_obj_reader`] and [`Mesh::from_stl_reader`] for what each format accepts.
    ///
    /// # Errors
    ///
    /// [`MeshError::UnsupportedFormat`] for any other extension (checked before the file is
    /// opened), [`MeshError::Io`] with the path if the file cannot be opened, and otherwise the
    /// reader function's errors, naming the file.
    pub fn load(path: impl AsRef<Path>) -> Result<Mesh, MeshError> {
        let path = path.as_ref();
        let extension = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        let is_obj = match extension.as_deref() {
            Some("obj") => true,
            Some("stl") => false,
            _ => {
                return Err(MeshError::UnsupportedFormat {
                    path: path.to_path_buf(),
                });
            }
        };
        let file = File::open(path).map_err(|source| MeshError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        let name = path.display().to_string();
        if is_obj {
            Mesh::from_obj_reader(BufReader::new(file), &name)
        } else {
            Mesh::from_stl_reader(BufReader::new(file), &name)
        }
    }

    /// Reads a Wavefront OBJ mesh. `source_name` (a file name, say) is only used in error
    /// messages.
    ///
    /// Every object and group (`o`, `g`) is merged into one mesh. Within one object the vertices
    /// are the file's own, minus those no face uses, renumbered in order of first use (that is
    /// what `tobj` returns). Because `tobj` numbers each object separately, a vertex shared by
    /// two objects is recognised by its identical parsed coordinates and merged. Texture
    /// coordinates, normals and materials are ignored (a `mtllib` is not opened).
    ///
    /// Coordinates are parsed to `f64` (tobj's `use_f64` feature), so the file's decimal values
    /// are read with correct rounding.
    ///
    /// # Errors
    ///
    /// * [`MeshError::NotTriangle`] naming the first face (or `l` line element) that is not a
    ///   triangle — polygons are never triangulated silently;
    /// * [`MeshError::Parse`] for malformed input, with the line number when the error is tied
    ///   to a line;
    /// * [`MeshError::Empty`] if there are no faces, and the other [`Mesh::try_new`] errors.
    pub fn from_obj_reader<R: BufRead>(reader: R, source_name: &str) -> Result<Mesh, MeshError> {
        // Faces as written (never triangulated), points and lines kept so that they can be
        // reported; every other option off (tobj's default).
        let options = tobj::LoadOptions {
            triangulate: false,
            ignore_points: false,
            ignore_lines: false,
            ..tobj::LoadOptions::default()
        };
        let mut counted = LineCounter::new(reader);
        // Materials are irrelevant here: refuse to open any library (tobj records the error in
        // the materials result, which is dropped).
        let loaded = tobj::load_obj_buf(&mut counted, &options, |_| {
            Err(tobj::LoadError::OpenFileFailed)
        });
        let models = match loaded {
            Ok((models, _materials)) => models,
            Err(e) => {
                let message = if counted.read_error {
                    format!("read error near line {}: {e}", counted.line())
                } else if is_tied_to_a_line(e) {
                    format!("line {}: {e}", counted.line())
                } else {
                    // Face indices are checked when an object is complete, not line by line.
                    format!("{e} (a face refers to an element the file does not define)")
                };
                return Err(MeshError::Parse {
                    source_name: source_name.to_owned(),
                    message,
                });
            }
        };

        let mut vertices: Vec<[f64; 3]> = Vec::new();
        let mut triangles: Vec<[u32; 3]> = Vec::new();
        // Exact parsed coordinates → merged index, for vertices of earlier objects.
        let mut earlier: HashMap<[u64; 3], u32> = HashMap::new();
        let mut faces_before = 0;
        for model in &models {
            let mesh = &model.mesh;
            if let Some(face) = mesh.face_arities.iter().position(|&a| a != 3) {
                return Err(MeshError::NotTriangle {
                    source_name: source_name.to_owned(),
                    face: faces_before + face,
                    vertices: mesh.face_arities[face] as usize,
                });
            }
            let local: Vec<u32> = mesh
                .positions
                .chunks_exact(3)
                .map(|p| {
                    if let Some(&i) = earlier.get(&bits_of(p)) {
                        return Ok(i);
                    }
                    let i = u32::try_from(vertices.len()).map_err(|_| MeshError::Parse {
                        source_name: source_name.to_owned(),
                        message: "more than 2^32 vertices".to_owned(),
                    })?;
                    vertices.push([p[0], p[1], p[2]]);
                    Ok(i)
                })
                .collect::<Result<_, MeshError>>()?;
            for (k, &i) in local.iter().enumerate() {
                earlier
                    .entry(bits_of(&mesh.positions[3 * k..3 * k + 3]))
                    .or_insert(i);
            }
            for t in mesh.indices.chunks_exact(3) {
                // tobj numbers each object's positions itself, so every index is in range; were
                // one not, u32::MAX makes try_new report it instead of a panic here.
                triangles
                    .push([0, 1, 2].map(|k| local.get(t[k] as usize).copied().unwrap_or(u32::MAX)));
            }
            faces_before += mesh.indices.len() / 3;
        }
        Mesh::try_new_named(vertices, triangles, Some(source_name))
    }

    /// Reads an STL mesh, ASCII or binary (`stl_io` decides: ASCII if the data starts with
    /// `solid `). `source_name` is only used in error messages.
    ///
    /// STL stores each triangle's corners separately; `stl_io` merges corners with identical
    /// coordinates into shared vertices, which is what makes an STL mesh [closed](Mesh::is_closed)
    /// when it should be. STL coordinates are `f32` (binary STL stores them so; ASCII STL is
    /// parsed so by `stl_io`) and are widened exactly. The stored facet normals are ignored.
    ///
    /// # Errors
    ///
    /// [`MeshError::Parse`] for malformed or truncated data, [`MeshError::Empty`] for an STL with
    /// no triangles, and the other [`Mesh::try_new`] errors (a NaN coordinate, say).
    pub fn from_stl_reader<R: Read + Seek>(
        mut reader: R,
        source_name: &str,
    ) -> Result<Mesh, MeshError> {
        let indexed = stl_io::read_stl(&mut reader).map_err(|e| MeshError::Parse {
            source_name: source_name.to_owned(),
            message: format!("invalid STL: {e}"),
        })?;
        let vertices = indexed
            .vertices
            .iter()
            .map(|v| v.0.map(f64::from))
            .collect();
        let mut triangles = Vec::with_capacity(indexed.faces.len());
        for face in &indexed.faces {
            let t = face.vertices.map(u32::try_from);
            match t {
                [Ok(a), Ok(b), Ok(c)] => triangles.push([a, b, c]),
                _ => {
                    return Err(MeshError::Parse {
                        source_name: source_name.to_owned(),
                        message: "more than 2^32 vertices".to_owned(),
                    });
                }
            }
        }
        Mesh::try_new_named(vertices, triangles, Some(source_name))
    }
}

/// The exact identity of a parsed position.
fn bits_of(p: &[f64]) -> [u64; 3] {
    [0, 1, 2].map(|k| p[k].to_bits())
}

/// Whether tobj raises this error while parsing a line (as opposed to when it assembles an
/// object, after the object's last line).
fn is_tied_to_a_line(e: tobj::LoadError) -> bool {
    !matches!(
        e,
        tobj::LoadError::FaceVertexOutOfBounds
            | tobj::LoadError::FaceTexCoordOutOfBounds
            | tobj::LoadError::FaceNormalOutOfBounds
            | tobj::LoadError::FaceColorOutOfBounds
    )
}

/// A `BufRead` that counts the lines its consumer has consumed, so that a parse error can say
/// where it happened. It also remembers whether the underlying reader failed.
struct LineCounter<R> {
    inner: R,
    lines: Lines,
    read_error: bool,
}

/// Newlines seen, and bytes since the last one.
#[derive(Default)]
struct Lines {
    newlines: usize,
    bytes_since_newline: usize,
}

impl Lines {
    fn count(&mut self, bytes: &[u8]) {
        for &b in bytes {
            if b == b'\n' {
                self.newlines += 1;
                self.bytes_since_newline = 0;
            } else {
                self.bytes_since_newline += 1;
            }
        }
    }
}

impl<R: BufRead> LineCounter<R> {
    fn new(inner: R) -> Self {
        LineCounter {
            inner,
            lines: Lines::default(),
            read_error: false,
        }
    }

    /// 1-based number of the line being read or last read.
    fn line(&self) -> usize {
        self.lines.newlines + usize::from(self.lines.bytes_since_newline > 0)
    }
}

impl<R: BufRead> Read for LineCounter<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self
            .inner
            .read(buf)
            .inspect_err(|_| self.read_error = true)?;
        self.lines.count(&buf[..n]);
        Ok(n)
    }
}

impl<R: BufRead> BufRead for LineCounter<R> {
    fn fill_buf(&mut self) -> io::Result<&[u8]> {
        match self.inner.fill_buf() {
            Ok(buf) => Ok(buf),
            Err(e) => {
                self.read_error = true;
                Err(e)
            }
        }
    }

    fn consume(&mut self, amount: usize) {
        // The consumer has just seen at least `amount` bytes from fill_buf, so the buffer is
        // still filled and this fill_buf does no I/O.
        if let Ok(buf) = self.inner.fill_buf() {
            self.lines.count(&buf[..amount.min(buf.len())]);
        }
        self.inner.consume(amount);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_line_counter_counts_consumed_lines() {
        let mut r = LineCounter::new(&b"a\nbb\nccc"[..]);
        let mut line = String::new();
        r.read_line(&mut line).unwrap();
        assert_eq!(r.line(), 1);
        r.read_line(&mut line).unwrap();
        assert_eq!(r.line(), 2);
        r.read_line(&mut line).unwrap();
        assert_eq!(r.line(), 3); // last line, no newline
    }

    #[test]
    fn a_bad_line_is_reported_by_number() {
        let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 x 0\nf 1 2 3\n";
        let e = Mesh::from_obj_reader(obj.as_bytes(), "bad.obj").unwrap_err();
        assert_eq!(
            e.to_string(),
            "mesh 'bad.obj': line 4: position parse error"
        );
    }

    #[test]
    fn objects_sharing_vertices_are_merged() {
        // A tetrahedron split into two objects: closed only if the shared vertices are merged.
        let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n\
                   o first\nf 1 3 2\nf 1 2 4\no second\nf 2 3 4\nf 1 4 3\n";
        let m = Mesh::from_obj_reader(obj.as_bytes(), "split.obj").unwrap();
        assert_eq!(m.vertices().len(), 4);
        assert_eq!(m.triangles().len(), 4);
        assert!(m.is_closed());
    }
}
