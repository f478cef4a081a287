//! The object wrench space from Python: built from a mesh file, mesh arrays or a disturbance
//! array (a task wrench space), and Q_OWS of grasps against it.

use crate::errors;
use crate::hull::float_array;
use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods};
use pqhull::grasp::FrictionModel;
use pqhull::grasp::ows::ObjectWrenchSpace as Space;
use pqhull::mesh::Mesh;
use pyo3::prelude::*;
use pyo3::types::PyList;

/// An object wrench space (the seed paper's Eq. 6 on a mesh) or a task wrench space (given
/// disturbances): the wrenches a grasp must resist, each `d` by `-r·d`.
///
/// Pickles exactly (the disturbances as binary numbers, the rest as JSON), so it can be sent to
/// other processes, e.g. through Ray's object store.
#[pyclass(module = "pqhull", name = "ObjectWrenchSpace", frozen)]
pub struct ObjectWrenchSpace {
    pub(crate) inner: Space,
}

/// The friction model, or a [`GraspError`](errors::GraspError) with the library's message.
pub(crate) fn friction(friction: f64, cone_edges: usize) -> PyResult<FrictionModel> {
    FrictionModel::try_new(friction, cone_edges).map_err(|e| errors::grasp(e.to_string()))
}

/// A two-dimensional numpy array handed to Python.
type Table<'py, T> = Bound<'py, PyArray2<T>>;

/// What `__reduce__` gives pickle: the function that rebuilds, and its arguments.
type Reduced<'py> = (Bound<'py, PyAny>, (Table<'py, f64>, String));

/// The rows of a (k, 6) array of wrenches.
fn disturbance_rows(wrenches: &Bound<'_, PyAny>) -> PyResult<Vec<[f64; 6]>> {
    let wrenches = float_array(wrenches, "wrenches")?;
    let wrenches: PyReadonlyArray2<'_, f64> = wrenches
        .extract()
        .map_err(|_| errors::input("wrenches must have shape (k, 6)"))?;
    if wrenches.shape()[1] != 6 {
        return Err(errors::input(format!(
            "wrenches must have shape (k, 6), not {:?}",
            wrenches.shape()
        )));
    }
    Ok(wrenches
        .as_array()
        .rows()
        .into_iter()
        .map(|r| std::array::from_fn(|j| r[j]))
        .collect())
}

/// The object wrench space of `mesh` (built without the GIL).
pub(crate) fn from_mesh(
    py: Python<'_>,
    mesh: &Mesh,
    model: FrictionModel,
) -> PyResult<ObjectWrenchSpace> {
    let inner = py
        .detach(|| Space::from_mesh(mesh, model))
        .map_err(|e| errors::grasp(e.to_string()))?;
    Ok(ObjectWrenchSpace { inner })
}

/// An OBJ or STL mesh from its file (read without the GIL).
fn load(py: Python<'_>, path: &std::path::Path) -> PyResult<Mesh> {
    py.detach(|| Mesh::load(path))
        .map_err(|e| errors::input(e.to_string()))
}

/// A mesh from an (n, 3) vertex array and an (f, 3) array of vertex indices (counter-clockwise
/// seen from outside).
fn mesh_of_arrays(
    py: Python<'_>,
    vertices: &Bound<'_, PyAny>,
    faces: &Bound<'_, PyAny>,
) -> PyResult<Mesh> {
    let vertices = float_array(vertices, "vertices")?;
    let vertices: PyReadonlyArray2<'_, f64> = vertices
        .extract()
        .map_err(|_| errors::input("vertices must have shape (n, 3)"))?;
    let numpy = py.import("numpy")?;
    let faces = numpy
        .call_method1("ascontiguousarray", (faces, "int64"))
        .map_err(|e| errors::input(format!("faces: not an array of integers ({e})")))?;
    let faces: PyReadonlyArray2<'_, i64> = faces
        .extract()
        .map_err(|_| errors::input("faces must have shape (f, 3)"))?;
    if vertices.shape()[1] != 3 || faces.shape()[1] != 3 {
        return Err(errors::input(format!(
            "vertices must have shape (n, 3) and faces (f, 3), not {:?} and {:?}",
            vertices.shape(),
            faces.shape()
        )));
    }
    let v: Vec<[f64; 3]> = vertices
        .as_array()
        .rows()
        .into_iter()
        .map(|r| [r[0], r[1], r[2]])
        .collect();
    let f = faces
        .as_array()
        .rows()
        .into_iter()
        .enumerate()
        .map(|(i, r)| {
            let index = |x: i64| {
                u32::try_from(x)
                    .map_err(|_| errors::input(format!("face {i}: index {x} out of range")))
            };
            Ok([index(r[0])?, index(r[1])?, index(r[2])?])
        })
        .collect::<PyResult<Vec<[u32; 3]>>>()?;
    Mesh::try_new(v, f).map_err(|e| errors::input(e.to_string()))
}

/// A mesh as the package takes one: the path of an OBJ or STL file (`str` or `os.PathLike`), or
/// a `(vertices, faces)` pair of arrays (a tuple or a list; what `load_mesh` returns).
pub(crate) fn mesh_of(py: Python<'_>, mesh: &Bound<'_, PyAny>) -> PyResult<Mesh> {
    if let Ok(path) = mesh.extract::<std::path::PathBuf>() {
        return load(py, &path);
    }
    let pair = match mesh.cast::<PyList>() {
        Ok(list) => list
            .to_tuple()
            .extract::<(Bound<'_, PyAny>, Bound<'_, PyAny>)>(),
        Err(_) => mesh.extract::<(Bound<'_, PyAny>, Bound<'_, PyAny>)>(),
    };
    match pair {
        Ok((vertices, faces)) => mesh_of_arrays(py, &vertices, &faces),
        Err(_) => Err(errors::input(format!(
            "mesh must be the path of an OBJ or STL file or a (vertices, faces) pair of arrays, \
             not {}",
            mesh.get_type().name()?
        ))),
    }
}

#[pymethods]
impl ObjectWrenchSpace {
    /// ObjectWrenchSpace.from_mesh(path, *, friction, cone_edges): the object wrench space of an
    /// OBJ or STL mesh, in the mesh's torque frame (centre of mass, largest vertex distance).
    #[staticmethod]
    #[pyo3(signature = (path, *, friction, cone_edges))]
    fn from_mesh(
        py: Python<'_>,
        path: std::path::PathBuf,
        friction: f64,
        cone_edges: usize,
    ) -> PyResult<Self> {
        let model = self::friction(friction, cone_edges)?;
        let mesh = load(py, &path)?;
        self::from_mesh(py, &mesh, model)
    }

    /// ObjectWrenchSpace.from_arrays(vertices, faces, *, friction, cone_edges): as `from_mesh`, for
    /// an (n, 3) vertex array and an (f, 3) array of vertex indices (counter-clockwise seen from
    /// outside).
    #[staticmethod]
    #[pyo3(signature = (vertices, faces, *, friction, cone_edges))]
    fn from_arrays(
        py: Python<'_>,
        vertices: &Bound<'_, PyAny>,
        faces: &Bound<'_, PyAny>,
        friction: f64,
        cone_edges: usize,
    ) -> PyResult<Self> {
        let model = self::friction(friction, cone_edges)?;
        let mesh = mesh_of_arrays(py, vertices, faces)?;
        self::from_mesh(py, &mesh, model)
    }

    /// ObjectWrenchSpace.from_disturbances(wrenches): a task wrench space, (k, 6) wrenches in the
    /// grasps' own torque units.
    #[staticmethod]
    fn from_disturbances(wrenches: &Bound<'_, PyAny>) -> PyResult<Self> {
        let rows = disturbance_rows(wrenches)?;
        let inner = Space::from_disturbances(rows).map_err(|e| errors::input(e.to_string()))?;
        Ok(ObjectWrenchSpace { inner })
    }

    /// The torque frame `(reference, scale)` grasps are evaluated in, or None for a task wrench
    /// space (the grasps' own frame).
    #[getter]
    fn torque_frame(&self) -> Option<([f64; 3], f64)> {
        self.inner.torque_frame()
    }

    /// The (k, 6) disturbance wrenches, in the grasps' torque units.
    #[getter]
    fn disturbances<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let flat = self.inner.disturbances().as_flattened().to_vec();
        PyArray1::from_vec(py, flat).reshape([self.inner.len(), 6])
    }

    /// Pickling: `_from_state(disturbances, description)`, where the description is the
    /// library's JSON of the space without its disturbances.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Reduced<'py>> {
        let py = slf.py();
        let mut description = slf.get().inner.to_json();
        if let Some(object) = description.as_object_mut() {
            object.remove("disturbances");
        }
        let rebuild = py.get_type::<Self>().getattr("_from_state")?;
        Ok((
            rebuild,
            (slf.get().disturbances(py)?, description.to_string()),
        ))
    }

    /// The inverse of `__reduce__`.
    #[staticmethod]
    fn _from_state(disturbances: &Bound<'_, PyAny>, description: &str) -> PyResult<Self> {
        let rows = disturbance_rows(disturbances)?;
        let description: serde_json::Value = serde_json::from_str(description)
            .map_err(|e| errors::input(format!("object wrench space description: {e}")))?;
        let inner =
            Space::from_json_parts(rows, &description).map_err(|e| errors::input(e.to_string()))?;
        Ok(ObjectWrenchSpace { inner })
    }

    fn __len__(&self) -> usize {
        self.inner.len()
    }

    fn __repr__(&self) -> String {
        format!("ObjectWrenchSpace({} disturbances)", self.inner.len())
    }
}

/// load_mesh(path): an OBJ or STL mesh as arrays `(vertices, faces)`: (n, 3) float64 positions
/// and (f, 3) int64 vertex indices of its triangles, as the library reads them (vertices no face
/// uses dropped, the rest in order of first use). `ObjectWrenchSpace.from_arrays` on them equals
/// `from_mesh(path)`.
#[pyfunction]
pub fn load_mesh<'py>(
    py: Python<'py>,
    path: std::path::PathBuf,
) -> PyResult<(Table<'py, f64>, Table<'py, i64>)> {
    let mesh = load(py, &path)?;
    let vertices = PyArray1::from_vec(py, mesh.vertices().as_flattened().to_vec())
        .reshape([mesh.vertices().len(), 3])?;
    let faces: Vec<i64> = mesh
        .triangles()
        .as_flattened()
        .iter()
        .map(|&i| i64::from(i))
        .collect();
    let faces = PyArray1::from_vec(py, faces).reshape([mesh.triangles().len(), 3])?;
    Ok((vertices, faces))
}
