// CGAL's exact hull of a 6-D point set, timed, for `compare_cgal` (cli/examples/compare_cgal.rs):
// a third exact engine beside pqhull and cddlib on the grasp sets where Qhull's answer is not
// the hull. Not part of any build or test: a comparison run by hand.
//
//   apt-get install libcgal-dev libeigen3-dev
//   g++ -O3 -DNDEBUG -std=c++17 -I/usr/include/eigen3 -DCGAL_EIGEN3_ENABLED
//       -o cgal_hull compare/cgal/hull.cpp -lgmpxx -lgmp -lmpfr   (one line)
//   PQHULL_CGAL=$PWD/cgal_hull ./target/release/examples/compare_cgal minkowski 6
//
// Input: the cddlib V-representation `compare_cgal` writes (`pqhull_cli::bench::cdd::write_ext`:
// rows "1 x1 ... x6", every coordinate the exact rational value of an f64), and the rounds to
// take the best time of.
// The engine: CGAL::Triangulation with the Epick_d kernel (exact predicates: a static filter,
// an interval filter, then exact arithmetic; the construction of points is never needed), whose
// infinite full cells are the hull's facets. It triangulates the interior too (the finite
// cells, printed), work a hull alone does not need: not a like-for-like hull time, but the
// time of a widely used exact engine on the same points. Insertion of a range
// sorts the points along a Hilbert curve first, as CGAL recommends.
#include <CGAL/Epick_d.h>
#include <CGAL/Triangulation.h>
#include <gmpxx.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Epick_d<CGAL::Dimension_tag<6>> Kernel;
typedef CGAL::Triangulation<Kernel> Triangulation;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: cgal_hull POINTS.ext [rounds]\n";
    return 2;
  }
  const int rounds = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  std::ifstream in(argv[1]);
  if (!in) {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 2;
  }
  std::string line;
  std::vector<Kernel::Point_d> points;
  size_t declared = 0, columns = 0;
  bool body = false;
  while (std::getline(in, line)) {
    if (line.rfind("begin", 0) == 0) {
      std::getline(in, line);
      std::istringstream head(line);
      head >> declared >> columns;
      if (columns != 7) {
        std::cerr << "expected 7 columns (1 and six coordinates), found " << columns << "\n";
        return 1;
      }
      body = true;
      continue;
    }
    if (!body || line.rfind("end", 0) == 0) continue;
    std::istringstream row(line);
    std::string token;
    row >> token;  // the homogenising 1
    std::vector<double> x;
    while (row >> token) {
      const mpq_class q(token);
      x.push_back(q.get_d());
      // The rationals are f64 values: the conversion must be exact.
      if (mpq_class(x.back()) != q) {
        std::cerr << "line " << line << ": " << token << " is not an f64\n";
        return 1;
      }
    }
    if (x.size() != 6) {
      std::cerr << "line " << line << ": expected 6 coordinates, found " << x.size() << "\n";
      return 1;
    }
    points.emplace_back(x.begin(), x.end());
  }
  if (points.size() != declared) {
    std::cerr << "expected " << declared << " points, read " << points.size() << "\n";
    return 1;
  }
  double best = 1e300;
  size_t facets = 0, cells = 0, vertices = 0;
  for (int r = 0; r < rounds; ++r) {
    const auto start = std::chrono::steady_clock::now();
    Triangulation t(6);
    t.insert(points.begin(), points.end());
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count();
    best = std::min(best, ms);
    cells = t.number_of_finite_full_cells();
    facets = t.number_of_full_cells() - cells;
    vertices = t.number_of_vertices();
  }
  std::printf(
      "CGAL Triangulation<Epick_d<6>> (best of %d) %.3f ms: %zu hull simplices, %zu points "
      "triangulated, %zu interior cells\n",
      rounds, best, facets, vertices, cells);
  return 0;
}
