#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <softopt/base/step_failure.h>
#include <softopt/physics/hyperelastic_problem.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cerrno>
#include <sstream>

namespace softopt
{
  namespace
  {
    constexpr unsigned int pressure_component = 3;
  } // namespace



  HyperelasticProblem::HyperelasticProblem(
    const Triangulation<3> &triangulation,
    const Mapping<3>       &mapping,
    const Geometry         &geometry,
    const Material  &material,
    const double            pressure)
    : triangulation_comm(triangulation.get_communicator())
    , triangulation(triangulation)
    , mapping(mapping)
    , geometry(geometry)
    , material(material)
    , pressure(pressure)
    , fe(FE_SimplexP<3>(2), 3, FE_SimplexDGP<3>(0), 1)
    , dof_handler(triangulation)
    , quadrature(2)
    , quadrature_face(3)
    , direct_solver(triangulation_comm)
  {}



  void
  HyperelasticProblem::setup_system()
  {
    dof_handler.distribute_dofs(fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);
    pressure_dofs = DoFTools::extract_dofs(dof_handler,
                                           ComponentMask({false, false, false, true}));

    // Zero displacement components on the Dirichlet boundaries. The face's
    // own DoF list decides which DoFs lie on it (FE_SimplexP's
    // has_support_on_face() answers true for every DoF in deal.II 9.4).
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto bc =
                geometry.dirichlet_boundaries.find(cell->face(f)->boundary_id());
              if (bc == geometry.dirichlet_boundaries.end())
                continue;
              cell->face(f)->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                {
                  const unsigned int c =
                    fe.face_system_to_component_index(i, f).first;
                  if (c < 3 && bc->second[c] &&
                      locally_relevant_dofs.is_element(face_dofs[i]))
                    constraints.add_line(face_dofs[i]);
                }
            }
    constraints.close();

    // Displacements couple with displacements; each element pressure only
    // with itself (its identity row after condensation).
    Table<2, DoFTools::Coupling> coupling(4, 4);
    for (unsigned int c = 0; c < 4; ++c)
      for (unsigned int d = 0; d < 4; ++d)
        coupling[c][d] = ((c < 3 && d < 3) || (c == 3 && d == 3)) ?
                           DoFTools::always :
                           DoFTools::none;
    DynamicSparsityPattern dsp(locally_relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler, coupling, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               triangulation_comm,
                                               locally_relevant_dofs);
    system_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         triangulation_comm);
    // The scatter also makes an entry outside the pattern an error (PETSc
    // would allocate it and force a new symbolic factorization).
    scatter.reinit(triangulation.n_active_cells());
  }



  HyperelasticProblem::Vector
  HyperelasticProblem::create_vector() const
  {
    return Vector(locally_owned_dofs, triangulation_comm);
  }



  HyperelasticProblem::Vector
  HyperelasticProblem::ghosted(const Vector &a) const
  {
    Vector g(locally_owned_dofs, locally_relevant_dofs, triangulation_comm);
    g = a;
    return g;
  }



  void
  HyperelasticProblem::assemble(const Vector &a,
                                const double  load_factor,
                                Vector       &residual,
                                Vector       &load,
                                const bool    with_tangent)
  {
    Timer        timer;
    const Vector a_ghost = ghosted(a);
    residual.reinit(locally_owned_dofs, triangulation_comm);
    load.reinit(locally_owned_dofs, triangulation_comm);
    for (Vec v : {static_cast<Vec>(residual), static_cast<Vec>(load)})
      VecSetOption(v, VEC_IGNORE_NEGATIVE_INDICES, PETSC_TRUE);
    if (with_tangent)
      {
        system_matrix = 0;
        scatter.begin(system_matrix);
        pressure_diagonal.clear();
      }

    FEValues<3>     fe_values(mapping,
                          fe,
                          quadrature,
                          update_values | update_gradients | update_JxW_values);
    FEFaceValues<3> fe_face_values(mapping,
                                   fe,
                                   quadrature_face,
                                   update_values | update_gradients |
                                     update_normal_vectors | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);

    const unsigned int n_dofs = fe.n_dofs_per_cell();
    const unsigned int n_q    = quadrature.size();
    FullMatrix<double> cell_matrix(n_dofs, n_dofs);
    dealii::Vector<double> cell_residual(n_dofs), cell_load(n_dofs), b(n_dofs);
    std::vector<types::global_dof_index> dof_indices(n_dofs);
    std::vector<Tensor<2, 3>>            grad_u(n_q);
    std::vector<Tensor<2, 3>>            grad_u_face(quadrature_face.size());
    std::vector<Tensor<2, 3>>            T(n_dofs);

    std::vector<unsigned int> component(n_dofs);
    unsigned int              pressure_dof = 0;
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        component[i] = fe.system_to_component_index(i).first;
        if (component[i] == pressure_component)
          pressure_dof = i;
      }
    cell_pressure_residual.assign(triangulation.n_active_cells(), 0.);
    cell_coupling.assign(triangulation.n_active_cells(), dealii::Vector<double>());
    cell_volume.assign(triangulation.n_active_cells(), 0.);

    const double bulk_modulus = material.bulk_modulus;
    const double p_hat        = pressure;
    bool         inverted     = false;
    double       diagonal_sum = 0;

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        fe_values.reinit(cell);
        fe_values[displacement].get_function_gradients(a_ghost, grad_u);
        cell->get_dof_indices(dof_indices);
        const double p_tilde = a_ghost(dof_indices[pressure_dof]);

        cell_matrix   = 0;
        cell_residual = 0;
        cell_load     = 0;
        b             = 0;
        double volume = 0, r_p = 0;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const Tensor<2, 3> F   = unit_symmetric_tensor<3>() + grad_u[q];
            const double J_minus_1 = jacobian_minus_one(grad_u[q]);
            const double JxW       = fe_values.JxW(q);
            inverted |= !(J_minus_1 > -1.);
            if (inverted)
              break;
            volume += JxW;
            // r_p = int (p - p~)/K dV with p = -K (J - 1) (Eq. res)
            r_p += (-J_minus_1 - p_tilde / bulk_modulus) * JxW;

            const Tensor<2, 3> P        = material.first_piola(F, p_tilde);
            const Tensor<2, 3> coupling = material.pressure_coupling(F);
            for (unsigned int i = 0; i < n_dofs; ++i)
              if (component[i] < 3)
                {
                  const Tensor<1, 3> &g_i = fe_values.shape_grad(i, q);
                  cell_residual(i) += P[component[i]] * g_i * JxW;
                  // b = -K_up = int J F^{-T} : grad N dV (Eq. LinMat)
                  b(i) -= coupling[component[i]] * g_i * JxW;
                }

            if (!with_tangent)
              continue;
            // K_uu = int grad N : A : grad N dV, with A = dP/dF (Eq. LinMat).
            const Tensor<4, 3> A = material.tangent(F, p_tilde);
            for (unsigned int j = 0; j < n_dofs; ++j)
              if (component[j] < 3)
                {
                  const Tensor<1, 3> &g_j = fe_values.shape_grad(j, q);
                  for (unsigned int k = 0; k < 3; ++k)
                    for (unsigned int l = 0; l < 3; ++l)
                      T[j][k][l] = A[k][l][component[j]] * g_j;
                }
            for (unsigned int i = 0; i < n_dofs; ++i)
              if (component[i] < 3)
                {
                  const Tensor<1, 3> &g_i = fe_values.shape_grad(i, q);
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    if (component[j] < 3)
                      cell_matrix(i, j) += T[j][component[i]] * g_i * JxW;
                }
          }
        if (inverted)
          continue;

        // Static condensation (Eq. statCond2) with K_up = -b and
        // K_pp = -|Omega^e| / K:
        //   r^e = r_u - K_up K_pp^{-1} r_p = r_u - K/|Omega^e| b r_p,
        //   K^e = K_uu - K_up K_pp^{-1} K_pu = K_uu + K/|Omega^e| b b^T.
        const double condensation = bulk_modulus / volume;
        cell_residual.add(-condensation * r_p, b);
        const unsigned int index      = cell->active_cell_index();
        cell_pressure_residual[index] = r_p;
        cell_coupling[index]          = b;
        cell_volume[index]            = volume;
        if (with_tangent)
          {
            double diagonal = 0;
            for (unsigned int i = 0; i < n_dofs; ++i)
              if (component[i] < 3)
                {
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    if (component[j] < 3)
                      cell_matrix(i, j) += condensation * b(i) * b(j);
                  diagonal += std::abs(cell_matrix(i, i));
                }
            // The condensed pressure DoF: a decoupled identity row of the
            // size of the displacement diagonal.
            cell_matrix(pressure_dof, pressure_dof) = diagonal / (n_dofs - 1);
          }

        // The follower pressure on the cavity walls (Eq. res and appendix):
        // p^ int N . n_c da with n_c da = J F^{-T} N dA (Nanson), the same
        // as n^_c dxi1 dxi2 of Eq. isoPressureLoad.
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              is_in(geometry.pressure_boundary_ids, cell->face(f)->boundary_id()))
            {
              fe_face_values.reinit(cell, f);
              fe_face_values[displacement].get_function_gradients(a_ghost,
                                                                  grad_u_face);
              for (unsigned int q = 0; q < quadrature_face.size(); ++q)
                {
                  const Tensor<2, 3> F =
                    unit_symmetric_tensor<3>() + grad_u_face[q];
                  const double       J = determinant(F);
                  const Tensor<2, 3> F_inv_T = transpose(invert(F));
                  const Tensor<1, 3> m =
                    F_inv_T * fe_face_values.normal_vector(q);
                  const double dA = fe_face_values.JxW(q);
                  for (unsigned int i = 0; i < n_dofs; ++i)
                    if (component[i] < 3)
                      cell_load(i) += p_hat * fe_face_values.shape_value(i, q) *
                                      J * m[component[i]] * dA;
                  if (!with_tangent)
                    continue;
                  // Load stiffness lambda K^p (Eq. dPdshape): the
                  // derivative of J F^{-T} N in the direction grad N_j e_d
                  // is J [(F^{-T} g_j)_d m - m_d F^{-T} g_j].
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    if (component[j] < 3)
                      {
                        const Tensor<1, 3> h =
                          F_inv_T * fe_face_values.shape_grad(j, q);
                        const unsigned int d = component[j];
                        for (unsigned int i = 0; i < n_dofs; ++i)
                          if (component[i] < 3)
                            cell_matrix(i, j) +=
                              load_factor * p_hat *
                              fe_face_values.shape_value(i, q) * J *
                              (h[d] * m[component[i]] -
                               m[d] * h[component[i]]) *
                              dA;
                      }
                }
            }

        cell_residual.add(load_factor, cell_load);
        add_to_global(cell->active_cell_index(),
                      with_tangent ? &cell_matrix : nullptr,
                      {&cell_residual, &cell_load},
                      dof_indices,
                      {&residual, &load});
        if (with_tangent)
          for (unsigned int i = 0; i < n_dofs; ++i)
            diagonal_sum += std::abs(cell_matrix(i, i));
      }


    // Constrained rows: zero residual, and a diagonal entry of the size of
    // the others so that the factorization sees a well-scaled identity.
    if (with_tangent)
      {
        scatter.end();
        for (const auto &[row, value] : pressure_diagonal)
          MatSetValue(system_matrix.petsc_matrix(), row, row, value, ADD_VALUES);
        add_constrained_diagonal(system_matrix, constraints, locally_owned_dofs, diagonal_sum);
      }

    residual.compress(VectorOperation::add);
    load.compress(VectorOperation::add);
    if (with_tangent)
      system_matrix.compress(VectorOperation::add);

    ++(with_tangent ? statistics.n_assemblies : statistics.n_residuals);
    (with_tangent ? statistics.assembly_time : statistics.residual_time) +=
      timer.wall_time();
    if (Utilities::MPI::logical_or(inverted, triangulation_comm))
      throw StepFailure("an element is inverted (J <= 0 at a quadrature "
                        "point)");
  }



  void
  HyperelasticProblem::add_to_global(
    const unsigned int                                 cell,
    const FullMatrix<double>                          *cell_matrix,
    const std::vector<const dealii::Vector<double> *> &cell_vectors,
    const std::vector<types::global_dof_index>        &dof_indices,
    const std::vector<Vector *>                       &vectors)
  {
    // Homogeneous Dirichlet constraints only: a constrained row or column is
    // dropped by giving it the index -1, which PETSc skips. The displacement
    // block and the pressure diagonal go in separately: the sparsity pattern
    // has no displacement-pressure couplings.
    const std::vector<PetscInt> rows = petsc_rows(dof_indices, constraints);
    const unsigned int          n    = rows.size();
    if (cell_matrix != nullptr)
      {
        std::vector<PetscInt>     u_rows;
        std::vector<unsigned int> u_local;
        for (unsigned int i = 0; i < n; ++i)
          if (fe.system_to_component_index(i).first != pressure_component)
            {
              u_local.push_back(i);
              u_rows.push_back(rows[i]);
            }
          else
            pressure_diagonal.emplace_back(rows[i], (*cell_matrix)(i, i));
        const unsigned int  n_u = u_local.size();
        std::vector<double> values(n_u * n_u);
        for (unsigned int i = 0; i < n_u; ++i)
          for (unsigned int j = 0; j < n_u; ++j)
            values[i * n_u + j] = (*cell_matrix)(u_local[i], u_local[j]);
        scatter.add(cell, u_rows, values.data());
      }
    for (unsigned int v = 0; v < vectors.size(); ++v)
      AssertThrow(VecSetValues(static_cast<Vec>(*vectors[v]),
                               n,
                               rows.data(),
                               cell_vectors[v]->data(),
                               ADD_VALUES) == 0,
                  ExcInternalError());
  }



  void
  HyperelasticProblem::factorize()
  {
    Timer timer;
    direct_solver.factorize(system_matrix);
    ++statistics.n_factorizations;
    statistics.factorization_time += timer.wall_time();
  }



  void
  HyperelasticProblem::solve(const Vector &b, Vector &x) const
  {
    Timer timer;
    x.reinit(locally_owned_dofs, triangulation_comm);
    direct_solver.solve(b, x);
    ++statistics.n_solves;
    statistics.solve_time += timer.wall_time();
    // The constrained entries are zero already (identity rows, zero right
    // hand side); distribute() keeps that exact.
    constraints.set_zero(x);
  }



  void
  HyperelasticProblem::solve_tangent(const Vector &b, Vector &x)
  {
    if (linear_solver.keep_factorization)
      solve_krylov(b, x, linear_solver.tolerance, linear_solver.max_iterations);
    else
      EquilibriumProblem::solve_tangent(b, x);
  }



  void
  HyperelasticProblem::solve_nearby_tangent(const Vector &b, Vector &x)
  {
    solve_krylov(b, x, linear_solver.tolerance, linear_solver.max_iterations);
  }



  void
  HyperelasticProblem::solve_kept(const Vector &b, Vector &x)
  {
    solve_krylov(b, x, DirectSolver::adjoint_tolerance, DirectSolver::adjoint_iterations);
  }



  void
  HyperelasticProblem::solve_krylov(const Vector      &b,
                                    Vector            &x,
                                    const double       tolerance,
                                    const unsigned int max_iterations)
  {
    Timer      timer;
    const auto result = direct_solver.solve_krylov(system_matrix, b, x, tolerance, max_iterations);
    statistics.n_factorizations += result.factorized;
    statistics.factorization_time += result.factorization_time;
    statistics.n_krylov_iterations += result.iterations;
    statistics.n_solves += result.iterations + result.factorized;
    statistics.solve_time += timer.wall_time() - result.factorization_time;
    constraints.set_zero(x);
  }



  void
  HyperelasticProblem::set_linear_solver(const DirectSolver::Parameters &parameters)
  {
    linear_solver = parameters;
    direct_solver.set_out_of_core(
      parameters.out_of_core_for(triangulation.n_global_active_cells()));
  }



  unsigned int
  HyperelasticProblem::n_negative_pivots() const
  {
    return direct_solver.n_negative_pivots();
  }



  void
  HyperelasticProblem::update(Vector &a, const Vector &du) const
  {
    // Eq. statCond1: dp~ = -K_pp^{-1} (r_p + K_pu du) = K/|Omega^e| (r_p - b.du)
    const Vector du_ghost = ghosted(du);
    a += du;
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dof_indices);
          const unsigned int index = cell->active_cell_index();
          double             b_du  = 0;
          types::global_dof_index pressure_index = 0;
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            if (fe.system_to_component_index(i).first == pressure_component)
              pressure_index = dof_indices[i];
            else
              b_du += cell_coupling[index](i) * du_ghost(dof_indices[i]);
          a(pressure_index) += material.bulk_modulus / cell_volume[index] *
                               (cell_pressure_residual[index] - b_du);
        }
    a.compress(VectorOperation::add);
  }



  void
  HyperelasticProblem::zero_condensed(Vector &v) const
  {
    for (const auto i : pressure_dofs)
      v(i) = 0;
    v.compress(VectorOperation::insert);
  }



  const PETScWrappers::MPI::SparseMatrix &
  HyperelasticProblem::tangent() const
  {
    return system_matrix;
  }



  void
  HyperelasticProblem::store_pressure(Vector &a) const
  {
    const Vector a_ghost = ghosted(a);
    FEValues<3>  fe_values(mapping, fe, quadrature, update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<Tensor<2, 3>>            grad_u(quadrature.size());
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(a_ghost, grad_u);
          double volume = 0, dilatation = 0;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              volume += fe_values.JxW(q);
              dilatation += jacobian_minus_one(grad_u[q]) * fe_values.JxW(q);
            }
          cell->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            if (fe.system_to_component_index(i).first == pressure_component)
              a(dof_indices[i]) = -material.bulk_modulus * dilatation / volume;
        }
    a.compress(VectorOperation::insert);
  }



  double
  HyperelasticProblem::min_jacobian(const Vector &a) const
  {
    const Vector a_ghost = ghosted(a);
    FEValues<3>  fe_values(mapping, fe, quadrature, update_gradients);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, 3>>        grad_u(quadrature.size());
    double                           J_min = std::numeric_limits<double>::max();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(a_ghost, grad_u);
          for (const auto &g : grad_u)
            J_min = std::min(J_min, determinant(unit_symmetric_tensor<3>() + g));
        }
    return Utilities::MPI::min(J_min, triangulation_comm);
  }



  std::string
  HyperelasticProblem::write_vtu(const Vector       &a,
                                 const std::string &directory,
                                 const std::string &name,
                                 const unsigned int counter) const
  {
    const Vector a_ghost = ghosted(a);

    // Cell means of J and of the Cauchy stress.
    const unsigned int n_cells = triangulation.n_active_cells();
    dealii::Vector<float> J_mean(n_cells), subdomain(n_cells);
    std::array<dealii::Vector<float>, 6> sigma;
    for (auto &s : sigma)
      s.reinit(n_cells);
    const std::array<std::pair<unsigned int, unsigned int>, 6> voigt{
      {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}}};

    FEValues<3> fe_values(mapping,
                          fe,
                          quadrature,
                          update_values | update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    const FEValuesExtractors::Scalar pressure_extractor(pressure_component);
    std::vector<Tensor<2, 3>>        grad_u(quadrature.size());
    std::vector<double>              p_tilde(quadrature.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(a_ghost, grad_u);
          fe_values[pressure_extractor].get_function_values(a_ghost, p_tilde);
          double       volume = 0, J_sum = 0;
          Tensor<2, 3> sigma_sum;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Tensor<2, 3> F = unit_symmetric_tensor<3>() + grad_u[q];
              volume += fe_values.JxW(q);
              J_sum += determinant(F) * fe_values.JxW(q);
              sigma_sum +=
                material.cauchy_stress(F, p_tilde[q]) * fe_values.JxW(q);
            }
          const unsigned int index = cell->active_cell_index();
          J_mean(index)            = J_sum / volume;
          for (unsigned int k = 0; k < 6; ++k)
            sigma[k](index) =
              sigma_sum[voigt[k].first][voigt[k].second] / volume;
          subdomain(index) = cell->subdomain_id();
        }

    DataOut<3> data_out;
    data_out.attach_dof_handler(dof_handler);
    std::vector<std::string> names(3, "displacement");
    names.emplace_back("pressure");
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(3,
                     DataComponentInterpretation::component_is_part_of_vector);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    data_out.add_data_vector(a_ghost,
                             names,
                             DataOut<3>::type_dof_data,
                             interpretation);
    data_out.add_data_vector(J_mean, "J", DataOut<3>::type_cell_data);
    const std::array<std::string, 6> sigma_names{
      {"sigma_xx", "sigma_yy", "sigma_zz", "sigma_yz", "sigma_xz", "sigma_xy"}};
    for (unsigned int k = 0; k < 6; ++k)
      data_out.add_data_vector(sigma[k], sigma_names[k], DataOut<3>::type_cell_data);
    data_out.add_data_vector(subdomain, "subdomain", DataOut<3>::type_cell_data);
    data_out.build_patches(mapping, 2);
    errno = 0;
    try
      {
        return data_out.write_vtu_with_pvtu_record(
          directory + "/", name, counter, triangulation_comm, 4);
      }
    catch (const ExceptionBase &e)
      {
        // deal.II's message names no file: name them, with the system's
        // last reason (errno) beside deal.II's words.
        std::ostringstream what;
        e.print_info(what);
        AssertThrow(false,
                    ExcMessage("Cannot write the VTU snapshot " + name + "_" +
                               Utilities::int_to_string(counter, 4) +
                               " into <" + directory + "> (" +
                               (errno != 0 ? std::strerror(errno) : "no system reason") +
                               "): " + Utilities::trim(what.str())));
      }
    return "";
  }



  const DoFHandler<3> &
  HyperelasticProblem::get_dof_handler() const
  {
    return dof_handler;
  }

  const Mapping<3> &
  HyperelasticProblem::get_mapping() const
  {
    return mapping;
  }

  const FESystem<3> &
  HyperelasticProblem::get_fe() const
  {
    return fe;
  }

  const Material &
  HyperelasticProblem::get_material() const
  {
    return material;
  }

  const Geometry &
  HyperelasticProblem::get_geometry() const
  {
    return geometry;
  }

  double
  HyperelasticProblem::get_pressure() const
  {
    return pressure;
  }

  const Quadrature<3> &
  HyperelasticProblem::cell_quadrature() const
  {
    return quadrature;
  }

  const Quadrature<2> &
  HyperelasticProblem::face_quadrature() const
  {
    return quadrature_face;
  }

  const AffineConstraints<double> &
  HyperelasticProblem::get_constraints() const
  {
    return constraints;
  }

  std::string
  HyperelasticProblem::Statistics::summary() const
  {
    std::ostringstream s;
    s << n_assemblies << " assemblies " << assembly_time << " s, "
      << n_factorizations << " factorizations " << factorization_time
      << " s, " << n_solves << " solves " << solve_time << " s, "
      << n_residuals << " residuals " << residual_time << " s, "
      << n_krylov_iterations << " GMRES iterations";
    return s.str();
  }



  HyperelasticProblem::Statistics &
  HyperelasticProblem::Statistics::operator+=(const Statistics &other)
  {
    n_assemblies += other.n_assemblies;
    n_factorizations += other.n_factorizations;
    n_solves += other.n_solves;
    n_residuals += other.n_residuals;
    n_krylov_iterations += other.n_krylov_iterations;
    assembly_time += other.assembly_time;
    factorization_time += other.factorization_time;
    solve_time += other.solve_time;
    residual_time += other.residual_time;
    return *this;
  }



  const HyperelasticProblem::Statistics &
  HyperelasticProblem::get_statistics() const
  {
    return statistics;
  }

  MPI_Comm
  HyperelasticProblem::get_communicator() const
  {
    return triangulation_comm;
  }
} // namespace softopt
