#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>

#include <softopt/shape/fictitious_material.h>
#include <softopt/shape/quadratic_tetrahedron.h>
#include <softopt/shape/shape_filter.h>
#include <softopt/solvers/petsc_check.h>
#include <softopt/solvers/refactorization_rule.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace softopt
{
  namespace
  {
    /** Read access to a ghosted vector's locally stored entries by
     * position (ShapeFilter::CellData::local): one PETSc call for the
     * whole vector instead of one per cell. */
    class LocalEntries
    {
    public:
      explicit LocalEntries(const PETScWrappers::MPI::Vector &v)
        : vector(v)
      {
        // A vector without ghosts has no local form: its own array then.
        check_petsc(VecGhostGetLocalForm(vector, &local), "VecGhostGetLocalForm");
        stored = local != nullptr ? local : vector;
        check_petsc(VecGetArrayRead(stored, &entries), "VecGetArrayRead");
        check_petsc(VecGetLocalSize(stored, &n_entries), "VecGetLocalSize");
      }

      ~LocalEntries()
      {
        VecRestoreArrayRead(stored, &entries);
        VecGhostRestoreLocalForm(vector, &local);
      }

      LocalEntries(const LocalEntries &) = delete;
      LocalEntries &
      operator=(const LocalEntries &) = delete;

      /** The entries at @p positions. */
      void
      extract(const std::vector<unsigned int> &positions, std::vector<double> &values) const
      {
        for (unsigned int i = 0; i < positions.size(); ++i)
          {
            AssertIndexRange(positions[i], n_entries);
            values[i] = entries[positions[i]];
          }
      }

    private:
      Vec                vector;
      Vec                local     = nullptr;
      Vec                stored    = nullptr; // local, or vector itself
      const PetscScalar *entries   = nullptr;
      PetscInt           n_entries = 0;
    };
  } // namespace



  void
  ShapeFilter::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Shape filter");
    prm.declare_entry("K_psi",
                      "1e-5",
                      Patterns::Double(0),
                      "Bulk-like modulus K_psi of the fictitious energy "
                      "(Eq. Wshape), in mm^-1: resists volume change of the "
                      "mesh.");
    prm.declare_entry("G_psi",
                      "1e-2",
                      Patterns::Double(0),
                      "Shear-like modulus G_psi of the fictitious energy "
                      "(Eq. Wshape), in mm^-1: larger values smooth the shape "
                      "field over longer distances (about sqrt(G_psi "
                      "|Omega_o|)) and keep elements better shaped; the "
                      "paper uses 1e-2 (gripper) and 3e-2.");
    prm.declare_entry("k_psi",
                      "10",
                      Patterns::Double(0),
                      "Exponent k_psi of the fictitious energy (Eq. Wshape), "
                      "dimensionless: stiffens compression of elements.");
    prm.declare_entry("Fixed boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 254)),
                      "Boundaries where the shape field psi is zero (the "
                      "shape cannot change there). Empty: every Dirichlet "
                      "boundary and every design boundary, as in the paper.");
    prm.leave_subsection();
  }



  void
  ShapeFilter::Parameters::parse_parameters(ParameterHandler &prm,
                                            const InputFile  &input)
  {
    prm.enter_subsection("Shape filter");
    K_psi              = prm.get_double("K_psi");
    G_psi              = prm.get_double("G_psi");
    k_psi              = prm.get_double("k_psi");
    fixed_boundary_ids = parse_boundary_ids(prm.get("Fixed boundary ids"),
                                            input.where("Shape filter",
                                                        "Fixed boundary ids"));
    prm.leave_subsection();
    AssertThrow(K_psi > 0 || G_psi > 0,
                ExcMessage(input.where("Shape filter", "G_psi") +
                           ": K_psi and G_psi cannot both be zero."));
  }



  ShapeFilter::ShapeFilter(const Parameters &parameters)
    : parameters(parameters)
  {}



  void
  ShapeFilter::setup(const DesignConfiguration &design_configuration,
                     const Geometry            &geometry)
  {
    design                         = &design_configuration;
    solution.reset();
    const DoFHandler<3> &dofs      = design->get_dof_handler();
    const MPI_Comm       comm      = dofs.get_communicator();
    const IndexSet       owned     = dofs.locally_owned_dofs();
    IndexSet             relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);

    std::vector<types::boundary_id> fixed = parameters.fixed_boundary_ids;
    if (fixed.empty())
      {
        for (const auto &[id, components] : geometry.dirichlet_boundaries)
          fixed.push_back(id);
        fixed.insert(fixed.end(),
                     geometry.design_boundary_ids.begin(),
                     geometry.design_boundary_ids.end());
      }
    constraints.clear();
    constraints.reinit(relevant);
    std::vector<types::global_dof_index> face_dofs(
      dofs.get_fe().n_dofs_per_face());
    for (const auto &cell : dofs.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && is_in(fixed, cell->face(f)->boundary_id()))
            {
              cell->face(f)->get_dof_indices(face_dofs);
              for (const auto i : face_dofs)
                if (relevant.is_element(i))
                  constraints.add_line(i);
            }
    constraints.close();

    // The tangent leaves out the fixed rows and columns (but their
    // diagonal): a smaller pattern for MUMPS. The mass matrix has all.
    for (const bool with_constraints : {true, false})
      {
        DynamicSparsityPattern dsp(relevant);
        if (with_constraints)
          DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
        else
          DoFTools::make_sparsity_pattern(dofs, dsp);
        SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
        (with_constraints ? matrix : mass_matrix).reinit(owned, owned, dsp, comm);
      }
    scatter.reinit(dofs.get_triangulation().n_active_cells());

    // The geometry of Omega_o at the quadrature points, then from it the
    // mass matrix of Omega_o (for dr_psi/dd) and |Omega_o|.
    const FiniteElement<3> &fe          = dofs.get_fe();
    const FiniteElement<3> &scalar      = fe.base_element(0);
    const unsigned int      n           = fe.n_dofs_per_cell();
    const unsigned int      n_functions = scalar.n_dofs_per_cell();
    const unsigned int      n_q         = quadrature().size();
    component_function.resize(n);
    std::vector<unsigned int> dof_of_function(n_functions);
    for (unsigned int i = 0; i < n; ++i)
      {
        component_function[i] = fe.system_to_component_index(i);
        if (component_function[i].first == 0)
          dof_of_function[component_function[i].second] = i;
      }
    shape_values.assign(n_q, std::vector<double>(n_functions));
    for (unsigned int q = 0; q < n_q; ++q)
      for (unsigned int b = 0; b < n_functions; ++b)
        shape_values[q][b] = scalar.shape_value(b, quadrature().point(q));

    FEValues<3> fe_values(design->get_initial_mapping(),
                          fe,
                          quadrature(),
                          update_gradients | update_JxW_values);
    FullMatrix<double>                   cell_mass(n, n);
    std::vector<types::global_dof_index> dof_indices(n);
    // A ghosted vector stores its owned entries, then its ghosts in the
    // order of relevant \ owned.
    IndexSet ghosts = relevant;
    ghosts.subtract_set(owned);
    cells.clear();
    volume = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          CellData data{fe_values.get_JxW_values(),
                        std::vector<Tensor<1, 3>>(n_q * n_functions),
                        {},
                        std::vector<unsigned int>(n),
                        cell->active_cell_index()};
          for (unsigned int q = 0; q < n_q; ++q)
            for (unsigned int b = 0; b < n_functions; ++b)
              data.grad[q * n_functions + b] =
                fe_values.shape_grad(dof_of_function[b], q);
          cell_mass = 0;
          for (unsigned int q = 0; q < n_q; ++q)
            {
              volume += data.JxW[q];
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  if (component_function[i].first == component_function[j].first)
                    cell_mass(i, j) += shape_values[q][component_function[i].second] *
                                       shape_values[q][component_function[j].second] *
                                       data.JxW[q];
            }
          cell->get_dof_indices(dof_indices);
          mass_matrix.add(dof_indices, cell_mass);
          data.rows = petsc_rows(dof_indices, constraints);
          for (unsigned int i = 0; i < n; ++i)
            data.local[i] = owned.is_element(dof_indices[i]) ?
                              owned.index_within_set(dof_indices[i]) :
                              owned.n_elements() + ghosts.index_within_set(dof_indices[i]);
          cells.push_back(std::move(data));
        }
    mass_matrix.compress(VectorOperation::add);
    volume = Utilities::MPI::sum(volume, comm);
    solver = std::make_unique<DirectSolver>(comm);
    solver->set_out_of_core(out_of_core);
  }



  ShapeFilter::Vector
  ShapeFilter::residual(const Vector &d, const Vector &psi, const bool with_tangent)
  {
    const DoFHandler<3>   &dofs  = design->get_dof_handler();
    const Vector           psi_g = design->ghosted(psi), d_g = design->ghosted(d);
    const FictitiousMaterial material(parameters.K_psi, parameters.G_psi, parameters.k_psi);
    const unsigned int     n           = component_function.size();
    const unsigned int     n_functions = shape_values[0].size();
    FullMatrix<double>     cell_matrix(n, n);
    dealii::Vector<double> cell_residual(n);
    std::vector<double>    psi_local(n), d_local(n), gap_local(n);
    std::vector<Tensor<2, 3>> T(n);

    Vector r(dofs.locally_owned_dofs(), dofs.get_communicator());
    VecSetOption(r, VEC_IGNORE_NEGATIVE_INDICES, PETSC_TRUE);
    if (with_tangent)
      {
        matrix = 0;
        scatter.begin(matrix);
      }
    const LocalEntries psi_entries(psi_g), d_entries(d_g);
    double             diagonal_sum = 0;
    bool               inverted     = false;
    for (const CellData &cell : cells)
      {
        psi_entries.extract(cell.local, psi_local);
        d_entries.extract(cell.local, d_local);
        for (unsigned int i = 0; i < n; ++i)
          gap_local[i] = psi_local[i] - d_local[i];
        cell_matrix   = 0;
        cell_residual = 0;
        for (unsigned int q = 0; q < cell.JxW.size(); ++q)
          {
            const Tensor<2, 3> F =
              unit_symmetric_tensor<3>() + gradient(cell, q, psi_local);
            if (!(determinant(F) > 0))
              {
                inverted = true;
                break;
              }
            // 1/2 from the potential (Eq. PDEpot01).
            const Tensor<2, 3> P    = 0.5 * material.first_piola(F);
            const Tensor<1, 3> gap  = value(q, gap_local) / volume;
            const double       JxW  = cell.JxW[q];
            const auto        *grad = &cell.grad[q * n_functions];
            const double      *N    = shape_values[q].data();
            for (unsigned int i = 0; i < n; ++i)
              {
                const auto [c, b] = component_function[i];
                cell_residual(i) += (P[c] * grad[b] + gap[c] * N[b]) * JxW;
              }
            if (!with_tangent)
              continue;
            // grad N_i : A : grad N_j through T_j = A : (e_{c_j} (x) g_j) JxW,
            // and the mass term N_i N_j / |Omega_o| on the diagonal blocks;
            // the upper triangle only (A has major symmetry), mirrored below.
            const Tensor<4, 3> A = (0.5 * JxW) * material.tangent(F);
            for (unsigned int j = 0; j < n; ++j)
              {
                const auto [c, b] = component_function[j];
                for (unsigned int k = 0; k < 3; ++k)
                  for (unsigned int l = 0; l < 3; ++l)
                    T[j][k][l] = A[k][l][c] * grad[b];
              }
            for (unsigned int i = 0; i < n; ++i)
              {
                const auto [c_i, b_i] = component_function[i];
                const double N_i      = N[b_i] * JxW / volume;
                for (unsigned int j = i; j < n; ++j)
                  {
                    const auto [c_j, b_j] = component_function[j];
                    cell_matrix(i, j) +=
                      T[j][c_i] * grad[b_i] + (c_i == c_j ? N_i * N[b_j] : 0.);
                  }
              }
          }
        AssertThrow(VecSetValues(r, n, cell.rows.data(), cell_residual.data(), ADD_VALUES) == 0,
                    ExcInternalError());
        if (with_tangent)
          {
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < i; ++j)
                cell_matrix(i, j) = cell_matrix(j, i);
            scatter.add(cell.active_index, cell.rows, &cell_matrix(0, 0));
            for (unsigned int i = 0; i < n; ++i)
              diagonal_sum += std::abs(cell_matrix(i, i));
          }
      }
    if (with_tangent)
      {
        scatter.end();
        add_constrained_diagonal(matrix, constraints, dofs.locally_owned_dofs(), diagonal_sum);
      }
    r.compress(VectorOperation::add);
    if (with_tangent)
      matrix.compress(VectorOperation::add);
    AssertThrow(!Utilities::MPI::logical_or(inverted, dofs.get_communicator()),
                ExcMessage("The shape filter met an inverted element (J_psi <= "
                           "0): the design moved too far for the mesh. Reduce "
                           "the design bound or the move limit, or increase "
                           "G_psi or K_psi (subsection \"Shape filter\")."));
    return r;
  }



  ShapeFilter::Result
  ShapeFilter::solve(const Vector &d, Vector &psi)
  {
    Vector Md = design->create_vector();
    mass_matrix.vmult(Md, d);
    constraints.set_zero(Md);
    const double scale = Md.l2_norm() / volume;

    // Converged when the residual is small against the coupling to d, or
    // when the update reaches the round-off of the positions (for a tiny d
    // the residual's round-off floor, about G_psi eps, stays above any
    // tolerance relative to d).
    Result       result;
    Vector       increment;
    const double tolerance = 1e-10;
    const double round_off = 1e-14 * design->initial_coordinates().linfty_norm();
    bool         small_update = false;
    // Modified Newton on the factorization kept from the last solve (the
    // previous design's tangent); steps that keep it assemble only the
    // residual.
    RefactorizationRule rule(solver->has_factorization());
    bool tangent_at_solution = false;
    for (unsigned int it = 0;; ++it)
      {
        tangent_at_solution = rule.certain();
        Vector       r      = residual(d, psi, tangent_at_solution);
        const double norm   = r.l2_norm();
        if (norm <= tolerance * scale || norm < 1e-300 || small_update)
          {
            result.iterations = it;
            break;
          }
        AssertThrow(it < 50 && std::isfinite(norm),
                    ExcMessage("The shape filter's Newton iteration did not "
                               "converge (|r| = " +
                               std::to_string(norm) +
                               "): the design is too far from the mesh. Reduce "
                               "the design bound or the move limit."));
        if (rule.refactorize(norm))
          {
            if (!tangent_at_solution)
              residual(d, psi, true);
            solver->factorize(matrix);
          }
        r *= -1.;
        increment.reinit(r);
        solver->solve(r, increment);
        constraints.set_zero(increment);
        psi += increment;
        small_update = increment.linfty_norm() <= round_off;
      }
    // The adjoint needs the tangent at the solution: assembled lazily.
    if (tangent_at_solution)
      solution.reset();
    else
      solution = std::make_unique<std::pair<Vector, Vector>>(d, psi);
    const Result health  = mesh_health(psi);
    result.min_J_psi     = health.min_J_psi;
    result.worst_quality = health.worst_quality;
    result.worst_element = health.worst_element;
    std::ostringstream message;
    message << "The shape field inverts elements (smallest J_psi = "
            << result.min_J_psi << ", worst element quality "
            << result.worst_quality << " at " << result.worst_element
            << " mm); the shape is refused. Reduce the "
            << "design bound or the move limit, or increase G_psi or K_psi "
            << "(subsection \"Shape filter\").";
    AssertThrow(result.min_J_psi > 0 && result.worst_quality > 0,
                ExcMessage(message.str()));
    return result;
  }



  void
  ShapeFilter::forget_factorization()
  {
    solver = std::make_unique<DirectSolver>(matrix.get_mpi_communicator());
    solver->set_out_of_core(out_of_core);
  }



  void
  ShapeFilter::set_linear_solver(const DirectSolver::Parameters &linear_solver)
  {
    Assert(design != nullptr, ExcMessage("ShapeFilter::setup() comes first"));
    out_of_core = linear_solver.out_of_core_for(
      design->get_dof_handler().get_triangulation().n_global_active_cells());
    if (solver)
      solver->set_out_of_core(out_of_core);
  }



  void
  ShapeFilter::solve_adjoint(const Vector &rhs, Vector &mu)
  {
    if (solution)
      {
        residual(solution->first, solution->second, true);
        solution.reset();
      }
    Vector b = rhs;
    constraints.set_zero(b);
    // The tangent is at the solution; the kept factorization is of a
    // nearby one.
    solver->solve_krylov(matrix, b, mu);
    constraints.set_zero(mu);
  }



  ShapeFilter::Vector
  ShapeFilter::design_gradient(const Vector &mu) const
  {
    Vector g = design->create_vector();
    mass_matrix.vmult(g, mu);
    g /= volume;
    return g;
  }



  ShapeFilter::Result
  ShapeFilter::mesh_health(const Vector &psi) const
  {
    const DoFHandler<3> &dofs  = design->get_dof_handler();
    const Vector         psi_g = design->ghosted(psi);
    Vector               X     = design->initial_coordinates();
    X += psi;
    const Vector        X_g = design->ghosted(X);
    const unsigned int  n   = component_function.size();
    std::vector<double> psi_local(n), X_local(n);
    Result              result;
    bool                has_cells = false;
    const LocalEntries  psi_entries(psi_g), X_entries(X_g);
    for (const CellData &cell : cells)
      {
        psi_entries.extract(cell.local, psi_local);
        X_entries.extract(cell.local, X_local);
        for (unsigned int q = 0; q < cell.JxW.size(); ++q)
          result.min_J_psi =
            std::min(result.min_J_psi,
                     determinant(unit_symmetric_tensor<3>() +
                                 gradient(cell, q, psi_local)));

        // The tetrahedron through the corner nodes of X.
        std::array<Point<3>, 4> p;
        for (unsigned int i = 0; i < n; ++i)
          {
            const auto [c, node] = component_function[i];
            if (node < 4)
              p[node][c] = X_local[i];
          }
        const double quality = mean_ratio(p);
        has_cells = true;
        if (quality < result.worst_quality)
          {
            result.worst_quality = quality;
            result.worst_element = 0.25 * (p[0] + p[1] + p[2] + p[3]);
          }
      }
    const MPI_Comm comm = dofs.get_communicator();
    result.min_J_psi    = Utilities::MPI::min(result.min_J_psi, comm);
    // The worst element's quality and rank, then its centroid from there.
    struct
    {
      double quality;
      int    rank;
    } worst{has_cells ? result.worst_quality : std::numeric_limits<double>::max(),
            static_cast<int>(Utilities::MPI::this_mpi_process(comm))};
    MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm);
    result.worst_quality = std::min(worst.quality, 1.);
    MPI_Bcast(&result.worst_element[0], 3, MPI_DOUBLE, worst.rank, comm);
    return result;
  }



  const QGaussSimplex<3> &
  ShapeFilter::quadrature()
  {
    static const QGaussSimplex<3> quadrature(2);
    return quadrature;
  }



  Tensor<2, 3>
  ShapeFilter::gradient(const CellData            &cell,
                        const unsigned int         q,
                        const std::vector<double> &v) const
  {
    const unsigned int n_functions = shape_values[q].size();
    Tensor<2, 3>       result;
    for (unsigned int i = 0; i < v.size(); ++i)
      {
        const auto [c, b] = component_function[i];
        result[c] += v[i] * cell.grad[q * n_functions + b];
      }
    return result;
  }



  Tensor<1, 3>
  ShapeFilter::value(const unsigned int q, const std::vector<double> &v) const
  {
    Tensor<1, 3> result;
    for (unsigned int i = 0; i < v.size(); ++i)
      {
        const auto [c, b] = component_function[i];
        result[c] += v[i] * shape_values[q][b];
      }
    return result;
  }



  const PETScWrappers::MPI::SparseMatrix &
  ShapeFilter::tangent() const
  {
    return matrix;
  }



  const AffineConstraints<double> &
  ShapeFilter::get_constraints() const
  {
    return constraints;
  }



  double
  ShapeFilter::initial_volume() const
  {
    return volume;
  }
} // namespace softopt
