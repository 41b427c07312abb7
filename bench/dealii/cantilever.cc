// Timoshenko's cantilever with deal.II (Q1, direct solver), for a side-by-side timing and
// accuracy comparison with vorodg's CG on quads (scripts/side_by_side_dealii.py).
//
// The problem is vorodg's core/problem/TimoshenkoBeam: [0, L] x [-D/2, D/2], L = 4, D = 1,
// E = 1, nu = 0.3, plane stress, end load P = 1, no body force. The exact displacement is
// interpolated at the nodes of x = 0, the exact (parabolic shear) traction is applied on x = L,
// top and bottom are traction-free (the exact traction vanishes there).
//
// Usage: cantilever N SOLVER    (4N x N cells; SOLVER umfpack or mumps)
// Prints one JSON line: {"n", "dofs", "solver", "l2_error", "seconds": {...}}.
#include <deal.II/base/function.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <dlfcn.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace cantilever
{
  using namespace dealii;
  constexpr int dim = 2;

  // Problem data, as in vorodg's TimoshenkoBeam (plane stress: E and nu are used as given).
  constexpr double L = 4.0, D = 1.0, E = 1.0, nu = 0.3, P = 1.0;
  constexpr double I = D * D * D / 12.0;
  constexpr double c = P / (6.0 * E * I);
  // Plane-stress Lame constants: lambda* = E nu / (1 - nu^2) gives
  // sigma_xx = E / (1 - nu^2) (eps_xx + nu eps_yy), the plane-stress law vorodg uses.
  constexpr double mu     = E / (2.0 * (1.0 + nu));
  constexpr double lambda = E * nu / (1.0 - nu * nu);

  // Colorized subdivided_hyper_rectangle boundary ids: 0 x = 0, 1 x = L, 2 bottom, 3 top.
  constexpr types::boundary_id clamped_end = 0, loaded_end = 1;

  // Exact displacement (TimoshenkoBeam::displacement).
  Tensor<1, dim> exact_displacement(const Point<dim> &p)
  {
    const double x = p[0], y = p[1];
    Tensor<1, dim> u;
    u[0] = -c * y * ((6 * L - 3 * x) * x + (2 + nu) * (y * y - D * D / 4));
    u[1] = c * (3 * nu * y * y * (L - x) + (4 + 5 * nu) * D * D * x / 4 +
                (3 * L - x) * x * x);
    return u;
  }

  // grad u, G[i][j] = du_i/dx_j (TimoshenkoBeam::gradient).
  Tensor<2, dim> exact_gradient(const Point<dim> &p)
  {
    const double   x = p[0], y = p[1];
    Tensor<2, dim> G;
    G[0][0] = -c * y * (6 * L - 6 * x);
    G[0][1] = -c * ((6 * L - 3 * x) * x + (2 + nu) * (3 * y * y - D * D / 4));
    G[1][0] = c * (-3 * nu * y * y + (4 + 5 * nu) * D * D / 4 + 6 * L * x - 3 * x * x);
    G[1][1] = c * 6 * nu * y * (L - x);
    return G;
  }

  // Exact traction sigma(u) n: derived from grad u, like ExactSolution::traction.
  Tensor<1, dim> exact_traction(const Point<dim> &p, const Tensor<1, dim> &n)
  {
    const Tensor<2, dim> G   = exact_gradient(p);
    const Tensor<2, dim> eps = 0.5 * (G + transpose(G));
    const Tensor<2, dim> sigma =
      lambda * trace(eps) * unit_symmetric_tensor<dim>() + 2 * mu * eps;
    return sigma * n;
  }

  // The exact displacement as a Function<2>, for the boundary values and the error.
  class ExactDisplacement : public Function<dim>
  {
  public:
    ExactDisplacement()
      : Function<dim>(dim)
    {}
    double value(const Point<dim> &p, const unsigned int component) const override
    {
      return exact_displacement(p)[component];
    }
    void vector_value(const Point<dim> &p, Vector<double> &values) const override
    {
      const Tensor<1, dim> u = exact_displacement(p);
      values[0]              = u[0];
      values[1]              = u[1];
    }
  };

  using Clock = std::chrono::steady_clock;
  double seconds_since(const Clock::time_point &t0)
  {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  }

  class CantileverProblem
  {
  public:
    CantileverProblem(unsigned int n, std::string solver);
    void run();

  private:
    void setup_system();
    void assemble_system();
    void solve();
    void compute_errors();
    void print_json() const;

    const unsigned int n;
    const std::string  solver_name;

    Triangulation<dim>        triangulation;
    DoFHandler<dim>           dof_handler;
    FESystem<dim>             fe;
    AffineConstraints<double> constraints;
    SparsityPattern           sparsity_pattern;
    SparseMatrix<double>      system_matrix;
    Vector<double>            solution, system_rhs;

    double l2_error = 0.0;
    double t_setup = 0, t_assembly = 0, t_solver = 0, t_error = 0, t_total = 0;
  };

  CantileverProblem::CantileverProblem(unsigned int n, std::string solver)
    : n(n)
    , solver_name(std::move(solver))
    , dof_handler(triangulation)
    , fe(FE_Q<dim>(1), dim)
  {}

  // Mesh, DoFs, constraints (the Dirichlet end) and the sparsity pattern.
  void CantileverProblem::setup_system()
  {
    const auto t0 = Clock::now();
    // 4n x n square cells of edge h = 1/n, as vorodg's `--family quad --h 1/n`.
    GridGenerator::subdivided_hyper_rectangle(
      triangulation, {4 * n, n}, Point<dim>(0, -D / 2), Point<dim>(L, D / 2), true);
    dof_handler.distribute_dofs(fe);

    // u = u_exact at the nodes of x = 0 (both components), as vorodg's CG does.
    constraints.clear();
    VectorTools::interpolate_boundary_values(dof_handler,
                                             clamped_end,
                                             ExactDisplacement(),
                                             constraints);
    constraints.close();

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    // Constrained rows/columns are condensed away during assembly, so leave them out here.
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    sparsity_pattern.copy_from(dsp);
    system_matrix.reinit(sparsity_pattern);
    solution.reinit(dof_handler.n_dofs());
    system_rhs.reinit(dof_handler.n_dofs());
    t_setup = seconds_since(t0);
  }

  void CantileverProblem::assemble_system()
  {
    const auto t0 = Clock::now();
    const QGauss<dim>     quadrature_formula(2);  // 2x2 Gauss: exact for Q1 stiffness
    const QGauss<dim - 1> face_quadrature_formula(2);
    FEValues<dim>         fe_values(fe,
                            quadrature_formula,
                            update_gradients | update_JxW_values);
    FEFaceValues<dim>     fe_face_values(fe,
                                     face_quadrature_formula,
                                     update_values | update_quadrature_points |
                                       update_normal_vectors | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);

    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    const unsigned int n_q_points    = quadrature_formula.size();
    FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
    Vector<double>     cell_rhs(dofs_per_cell);
    std::vector<types::global_dof_index> local_dof_indices(dofs_per_cell);
    std::vector<SymmetricTensor<2, dim>> sym_grad(dofs_per_cell);
    std::vector<double>                  div(dofs_per_cell);

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell_matrix = 0;
        cell_rhs    = 0;
        fe_values.reinit(cell);

        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            for (unsigned int k = 0; k < dofs_per_cell; ++k)
              {
                sym_grad[k] = fe_values[displacement].symmetric_gradient(k, q);
                div[k]      = fe_values[displacement].divergence(k, q);
              }
            // a(u, v) = (2 mu eps(u) : eps(v) + lambda div u div v)_K, i.e. (sigma(u), eps(v))
            // with the plane-stress lambda*.
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              for (unsigned int j = 0; j < dofs_per_cell; ++j)
                cell_matrix(i, j) += (2 * mu * (sym_grad[i] * sym_grad[j]) +
                                      lambda * div[i] * div[j]) *
                                     fe_values.JxW(q);
          }
        // No body force term: the beam is in equilibrium with b = 0.

        // l(v) = <t, v> on x = L with the exact parabolic shear traction. Top and bottom
        // are traction-free, so they contribute nothing.
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == loaded_end)
            {
              fe_face_values.reinit(cell, face);
              for (unsigned int q = 0; q < face_quadrature_formula.size(); ++q)
                {
                  const Tensor<1, dim> t =
                    exact_traction(fe_face_values.quadrature_point(q),
                                   fe_face_values.normal_vector(q));
                  for (unsigned int i = 0; i < dofs_per_cell; ++i)
                    cell_rhs(i) += fe_face_values[displacement].value(i, q) * t *
                                   fe_face_values.JxW(q);
                }
            }

        cell->get_dof_indices(local_dof_indices);
        // Eliminates the Dirichlet DOFs and moves K u_D to the right side (the lifting).
        constraints.distribute_local_to_global(
          cell_matrix, cell_rhs, local_dof_indices, system_matrix, system_rhs);
      }
    t_assembly = seconds_since(t0);
  }

  // Factorization and solve; then the constrained DOFs get their prescribed values.
  void CantileverProblem::solve()
  {
    const auto t0 = Clock::now();
    if (solver_name == "umfpack")
      {
        SparseDirectUMFPACK umfpack;
        umfpack.initialize(system_matrix);  // symbolic + numeric factorization
        solution = system_rhs;
        umfpack.solve(solution);
      }
#ifdef DEAL_II_WITH_MUMPS
    else if (solver_name == "mumps")
      {
        // Not compiled with deal.II 9.4 (its SparseDirectMUMPS was removed in 2015 and came
        // back in 9.7); kept for a deal.II configured with DEAL_II_WITH_MUMPS.
        SparseDirectMUMPS mumps;
        mumps.initialize(system_matrix);
        mumps.vmult(solution, system_rhs);
      }
#endif
    else
      throw std::runtime_error("unknown solver " + solver_name);
    constraints.distribute(solution);
    t_solver = seconds_since(t0);
  }

  // ||u_h - u|| / ||u||, L2 over the domain. QGauss(4) integrates the squared error exactly:
  // u is cubic and u_h bilinear, so |u_h - u|^2 has degree <= 6 in each variable (<= 7).
  void CantileverProblem::compute_errors()
  {
    const auto        t0 = Clock::now();
    const QGauss<dim> quadrature(4);
    const ExactDisplacement exact;
    Vector<float>     per_cell(triangulation.n_active_cells());

    VectorTools::integrate_difference(
      dof_handler, solution, exact, per_cell, quadrature, VectorTools::L2_norm);
    const double error =
      VectorTools::compute_global_error(triangulation, per_cell, VectorTools::L2_norm);

    // ||u|| with the same rule: the difference between a zero field and u.
    const Vector<double> zero(dof_handler.n_dofs());
    VectorTools::integrate_difference(
      dof_handler, zero, exact, per_cell, quadrature, VectorTools::L2_norm);
    const double norm =
      VectorTools::compute_global_error(triangulation, per_cell, VectorTools::L2_norm);

    l2_error = error / norm;
    t_error  = seconds_since(t0);
  }

  void CantileverProblem::print_json() const
  {
    std::printf("{\"n\":%u,\"dofs\":%u,\"solver\":\"%s\",\"l2_error\":%.10e,"
                "\"seconds\":{\"setup\":%.6f,\"assembly\":%.6f,\"solver\":%.6f,"
                "\"error\":%.6f,\"total\":%.6f}}\n",
                n,
                static_cast<unsigned int>(dof_handler.n_dofs()),
                solver_name.c_str(),
                l2_error,
                t_setup,
                t_assembly,
                t_solver,
                t_error,
                t_total);
  }

  void CantileverProblem::run()
  {
    const auto t0 = Clock::now();
    setup_system();
    assemble_system();
    solve();
    compute_errors();
    t_total = seconds_since(t0);
    print_json();
  }

  // One BLAS thread (UMFPACK calls the BLAS; OpenBLAS otherwise starts one per core).
  void limit_blas_threads()
  {
    using SetFn = void (*)(int);
    if (auto set = reinterpret_cast<SetFn>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set(1);
  }
} // namespace cantilever

int main(int argc, char **argv)
{
  using namespace dealii;
  // One thread for deal.II's own parallel loops (TBB); checked below.
  MultithreadInfo::set_thread_limit(1);
  cantilever::limit_blas_threads();
  try
    {
      if (argc != 3)
        throw std::invalid_argument("usage: cantilever N SOLVER (SOLVER umfpack or mumps)");
      char              *end = nullptr;
      const long         n   = std::strtol(argv[1], &end, 10);
      const std::string  solver(argv[2]);
      if (*end != '\0' || n < 1 || n > 100000)
        throw std::invalid_argument(std::string("N '") + argv[1] +
                                    "': expected an integer in [1, 100000]");
      if (solver != "umfpack" && solver != "mumps")
        throw std::invalid_argument("SOLVER '" + solver + "': expected umfpack or mumps");
      if (MultithreadInfo::n_threads() != 1)
        throw std::runtime_error("expected one thread, MultithreadInfo says " +
                                 std::to_string(MultithreadInfo::n_threads()));
#ifndef DEAL_II_WITH_MUMPS
      if (solver == "mumps")
        {
          // Said in the output, not an error: the comparison script shows it as skipped.
          std::printf("{\"n\":%ld,\"solver\":\"mumps\",\"skipped\":\"deal.II %s was not "
                      "configured with MUMPS (no DEAL_II_WITH_MUMPS)\"}\n",
                      n,
                      DEAL_II_PACKAGE_VERSION);
          return 0;
        }
#else
      // SparseDirectMUMPS runs on MPI_COMM_WORLD.
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
#endif
      cantilever::CantileverProblem problem(static_cast<unsigned int>(n), solver);
      problem.run();
    }
  catch (std::exception &exc)
    {
      std::cerr << "cantilever: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
