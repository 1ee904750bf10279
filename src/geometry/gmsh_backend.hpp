#pragma once
// Private to the geometry layer: everything that talks to the Gmsh library.
#include "geometry/mesh.hpp"

#include <mutex>
#include <string>
#include <vector>

namespace kessler::geometry::detail {

// Gmsh keeps its model in global state: one session at a time in the process. The session
// holds a process-wide lock, initialises Gmsh quietly and deterministically (no config files,
// no terminal output, one thread) and finalises it on destruction, so nothing leaks between
// calls.
class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  std::unique_lock<std::mutex> lock_;
  // Gmsh's General.NumThreads calls omp_set_num_threads: the caller's thread count is put back
  // when the session ends, or every run after meshing would be single-threaded.
  int omp_threads_ = 1;
};

// Describes the exception in flight (call from a catch block inside a session): Gmsh 4.8
// throws its last error message as a std::string, newer versions a std::exception.
std::string currentGmshError();

// The linear tetrahedra of the current Gmsh model, vertices scaled by `scale` and renumbered
// compactly (only vertices used by a tet, in increasing Gmsh tag order). Orientation as Gmsh
// stores it.
TetMesh extractTets(double scale);

// Meshes an analytic shape (validated by the caller).
TetMesh generateMesh(const MeshRequest& request);

// Reads the tetrahedra of a Gmsh .msh file, scaled to metres; errors name the file.
TetMesh importMesh(const MeshFile& file);

}  // namespace kessler::geometry::detail
