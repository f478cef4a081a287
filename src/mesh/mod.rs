//! Triangle meshes: loading (OBJ, STL), mass properties and surface normals.
