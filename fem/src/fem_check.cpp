// The P1 Poisson sanity check: -lap u = f on the tet mesh, Dirichlet data from the exact solution
// on the boundary nodes. Weak form: sum_j u_j int grad phi_j . grad phi_i = int f phi_i for every
// interior node i, with the boundary values moved to the right-hand side.

#include "meshprep/fem/fem_check.h"

#include "meshprep/core/errors.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace meshprep {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// A problem with a known solution: u and the constant f = -lap u.
struct Problem {
  double (*exact)(const Vec3&);
  double load;
};

double linear_field(const Vec3& p) { return 1.0 + 2.0 * p.x() - 3.0 * p.y() + 0.5 * p.z(); }
double quadratic_field(const Vec3& p) { return p.squaredNorm(); }

// Column 0 of every right-hand side and solution: the patch test; column 1: the quadratic.
constexpr std::array<Problem, 2> kProblems{{{linear_field, 0.0}, {quadratic_field, -6.0}}};
constexpr Eigen::Index kPatch = 0, kPoisson = 1;

// CG stopping criterion ||K x - b|| <= tol ||b||: near round-off, so that the patch test measures
// the mesh, not the solver.
constexpr double kRelativeResidual = 1e-14;

// The symmetric 14-point rule of degree 5 with positive weights (orbits of 4 + 4 + 6 points in
// barycentric coordinates), exact for the degree-4 integrands (u_h - u)^2 and u^2. Weights sum
// to 1 (multiply by the volume); the constants solve the rule's moment equations to 20 digits.
struct QuadraturePoint {
  std::array<double, 4> barycentric;
  double weight;
};

std::vector<QuadraturePoint> degree5_rule() {
  std::vector<QuadraturePoint> rule;
  auto vertex_orbit = [&](double a, double w) {
    for (int k = 0; k < 4; ++k) {
      std::array<double, 4> b{a, a, a, a};
      b[k] = 1.0 - 3.0 * a;
      rule.push_back({b, w});
    }
  };
  auto edge_orbit = [&](double a, double w) {
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        std::array<double, 4> b{0.5 - a, 0.5 - a, 0.5 - a, 0.5 - a};
        b[i] = b[j] = a;
        rule.push_back({b, w});
      }
  };
  vertex_orbit(0.09273525031089122745, 0.07349304311636195232);
  vertex_orbit(0.31088591926330061369, 0.11268792571801585164);
  edge_orbit(0.04550370412564965528, 0.04254602077708146403);
  return rule;
}

void validate(const TetMesh& mesh) {
  if (mesh.tets.empty()) throw InvalidInput("fem check: the mesh has no tetrahedra");
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (const auto v : mesh.tets[t])
      if (v >= mesh.points.size())
        throw InvalidInput("fem check: tet " + std::to_string(t) + " references point " + std::to_string(v) +
                           " of " + std::to_string(mesh.points.size()));
    if (!(tet_volume(mesh, t) > 0))
      throw InvalidInput("fem check: tet " + std::to_string(t) + " is inverted or flat (volume " +
                         std::to_string(tet_volume(mesh, t)) + ")");
  }
  for (const auto& f : mesh.boundary_faces)
    for (const auto v : f)
      if (v >= mesh.points.size())
        throw InvalidInput("fem check: a boundary face references point " + std::to_string(v) + " of " +
                           std::to_string(mesh.points.size()));
}

// Faces used by exactly one tet, as sorted vertex triples.
std::vector<Triangle> faces_used_once(const TetMesh& mesh) {
  std::vector<Triangle> faces;
  faces.reserve(4 * mesh.tets.size());
  for (const auto& t : mesh.tets)
    for (int k = 0; k < 4; ++k) {
      Triangle f{t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]};
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end());
  std::vector<Triangle> once;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    if (j - i == 1) once.push_back(faces[i]);
    i = j;
  }
  return once;
}

// Dirichlet nodes: the vertices of the boundary faces (derived from the tets when there are none).
std::vector<bool> dirichlet_nodes(const TetMesh& mesh) {
  std::vector<bool> on_boundary(mesh.points.size(), false);
  auto mark = [&](const std::vector<Triangle>& faces) {
    for (const auto& f : faces)
      for (const auto v : f) on_boundary[v] = true;
  };
  if (mesh.boundary_faces.empty())
    mark(faces_used_once(mesh));
  else
    mark(mesh.boundary_faces);
  return on_boundary;
}

// The index of every point's unknown: -1 for Dirichlet nodes and for points no tet uses.
struct Numbering {
  std::vector<Eigen::Index> unknown;
  std::vector<bool> used;
  Eigen::Index count = 0;
};

Numbering number_unknowns(const TetMesh& mesh) {
  Numbering n;
  n.used.assign(mesh.points.size(), false);
  for (const auto& t : mesh.tets)
    for (const auto v : t) n.used[v] = true;
  const std::vector<bool> on_boundary = dirichlet_nodes(mesh);
  n.unknown.assign(mesh.points.size(), -1);
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (n.used[v] && !on_boundary[v]) n.unknown[v] = n.count++;
  return n;
}

// Gradients of the barycentric coordinates (the P1 shape functions) of a tet with edges a, b, c
// from p0: the rows of [a b c]^-1, i.e. (b x c, c x a, a x b) / (a . (b x c)); grad l0 = -sum.
std::array<Vec3, 4> shape_gradients(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double det = a.dot(b.cross(c));
  const Vec3 g1 = b.cross(c) / det, g2 = c.cross(a) / det, g3 = a.cross(b) / det;
  return {-(g1 + g2 + g3), g1, g2, g3};
}

// The reduced system: the lower triangle of the stiffness matrix over the unknowns and one
// right-hand side per problem (load minus the coupling to the Dirichlet values).
struct LinearSystem {
  SparseMatrix lower;
  Eigen::MatrixXd rhs;
};

void add_element(const TetMesh& mesh, const Numbering& n, const Tetrahedron& tet,
                 std::vector<Eigen::Triplet<double>>& triplets, Eigen::MatrixXd& rhs) {
  const Vec3& p0 = mesh.points[tet[0]];
  const Vec3 a = mesh.points[tet[1]] - p0, b = mesh.points[tet[2]] - p0, c = mesh.points[tet[3]] - p0;
  const double volume = a.dot(b.cross(c)) / 6.0;
  const std::array<Vec3, 4> grad = shape_gradients(a, b, c);
  for (int i = 0; i < 4; ++i) {
    const Eigen::Index row = n.unknown[tet[i]];
    if (row < 0) continue;
    for (std::size_t p = 0; p < kProblems.size(); ++p) rhs(row, Eigen::Index(p)) += kProblems[p].load * volume / 4.0;
    for (int j = 0; j < 4; ++j) {
      const double k_ij = volume * grad[i].dot(grad[j]);  // int grad phi_i . grad phi_j, gradients constant
      const Eigen::Index col = n.unknown[tet[j]];
      if (col < 0) {
        for (std::size_t p = 0; p < kProblems.size(); ++p)
          rhs(row, Eigen::Index(p)) -= k_ij * kProblems[p].exact(mesh.points[tet[j]]);
      } else if (col <= row) {
        triplets.emplace_back(row, col, k_ij);
      }
    }
  }
}

LinearSystem assemble(const TetMesh& mesh, const Numbering& n) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(10 * mesh.tets.size());  // 4 diagonal + 6 off-diagonal entries per tet at most
  LinearSystem s;
  s.rhs = Eigen::MatrixXd::Zero(n.count, Eigen::Index(kProblems.size()));
  for (const auto& tet : mesh.tets) add_element(mesh, n, tet, triplets, s.rhs);
  s.lower.resize(n.count, n.count);
  s.lower.setFromTriplets(triplets.begin(), triplets.end());
  return s;
}

// Jacobi-preconditioned conjugate gradients: O(nnz) memory, ~200 iterations for 2e5 unknowns on
// a uniform mesh (about 1 s; an incomplete Cholesky preconditioner saved few iterations and cost 6x
// the time). A sparse LDL^T factorisation is exact but its fill grows superlinearly on 3D meshes
// (10 s for 3e4 unknowns, minutes beyond 1e5), so it only takes over when CG does not converge.
Eigen::MatrixXd solve(const LinearSystem& s) {
  if (s.lower.rows() == 0) return Eigen::MatrixXd(0, s.rhs.cols());
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower> cg;
  cg.setTolerance(kRelativeResidual);
  cg.compute(s.lower);
  if (cg.info() == Eigen::Success) {
    Eigen::MatrixXd x = cg.solve(s.rhs);
    if (cg.info() == Eigen::Success) return x;
  }
  const Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt(s.lower);
  if (ldlt.info() == Eigen::Success) {
    Eigen::MatrixXd x = ldlt.solve(s.rhs);
    if (x.allFinite()) return x;
  }
  throw SolverError("fem check: conjugate gradients stopped at relative residual " + std::to_string(cg.error()) +
                    " after " + std::to_string(cg.iterations()) +
                    " iterations and the sparse LDL^T factorisation failed");
}

// Nodal values of the discrete solution of problem p: solved unknowns, Dirichlet data elsewhere.
Eigen::VectorXd nodal_values(const TetMesh& mesh, const Numbering& n, const Eigen::MatrixXd& x, Eigen::Index p) {
  Eigen::VectorXd u(Eigen::Index(mesh.points.size()));
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    u[Eigen::Index(v)] = n.unknown[v] >= 0 ? x(n.unknown[v], p) : kProblems[std::size_t(p)].exact(mesh.points[v]);
  return u;
}

// max |u_h - u| / max |u| over the nodes of the tets.
double max_relative_nodal_error(const TetMesh& mesh, const Numbering& n, const Eigen::VectorXd& u_h,
                                double (*exact)(const Vec3&)) {
  double error = 0, scale = 0;
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    if (!n.used[v]) continue;
    const double u = exact(mesh.points[v]);
    error = std::max(error, std::abs(u_h[Eigen::Index(v)] - u));
    scale = std::max(scale, std::abs(u));
  }
  return scale > 0 ? error / scale : error;
}

struct L2Norms {
  double error = 0;  ///< ||u_h - u||
  double exact = 0;  ///< ||u||
};

L2Norms l2_norms(const TetMesh& mesh, const Eigen::VectorXd& u_h, double (*exact)(const Vec3&)) {
  const std::vector<QuadraturePoint> rule = degree5_rule();
  double error_sq = 0, exact_sq = 0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& tet = mesh.tets[t];
    const double volume = tet_volume(mesh, t);
    for (const auto& q : rule) {
      Vec3 x = Vec3::Zero();
      double discrete = 0;
      for (int k = 0; k < 4; ++k) {
        x += q.barycentric[k] * mesh.points[tet[k]];
        discrete += q.barycentric[k] * u_h[Eigen::Index(tet[k])];
      }
      const double u = exact(x);
      error_sq += q.weight * volume * (discrete - u) * (discrete - u);
      exact_sq += q.weight * volume * u * u;
    }
  }
  return {std::sqrt(error_sq), std::sqrt(exact_sq)};
}

double longest_edge(const TetMesh& mesh) {
  double longest_sq = 0;
  for (const auto& t : mesh.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        longest_sq = std::max(longest_sq, (mesh.points[t[i]] - mesh.points[t[j]]).squaredNorm());
  return std::sqrt(longest_sq);
}

}  // namespace

FemCheckResult run_fem_check(const TetMesh& mesh) {
  validate(mesh);
  const Numbering numbering = number_unknowns(mesh);
  const Eigen::MatrixXd x = solve(assemble(mesh, numbering));
  FemCheckResult r;
  r.unknowns = std::size_t(numbering.count);
  r.solver_converged = true;  // solve() throws otherwise
  r.patch_test_max_error = max_relative_nodal_error(mesh, numbering, nodal_values(mesh, numbering, x, kPatch),
                                                    kProblems[kPatch].exact);
  const L2Norms l2 = l2_norms(mesh, nodal_values(mesh, numbering, x, kPoisson), kProblems[kPoisson].exact);
  r.poisson_l2_error = l2.error;
  r.poisson_l2_relative = l2.exact > 0 ? l2.error / l2.exact : l2.error;
  r.h_max = longest_edge(mesh);
  return r;
}

nlohmann::ordered_json to_json(const FemCheckResult& result) {
  return {{"patch_test_max_error", result.patch_test_max_error},
          {"poisson_l2_error", result.poisson_l2_error},
          {"poisson_l2_relative", result.poisson_l2_relative},
          {"h_max", result.h_max},
          {"unknowns", result.unknowns},
          {"solver_converged", result.solver_converged}};
}

}  // namespace meshprep
