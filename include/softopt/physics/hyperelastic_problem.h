#ifndef softopt_physics_hyperelastic_problem_h
#define softopt_physics_hyperelastic_problem_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <softopt/geometry/geometry.h>
#include <softopt/path/equilibrium_problem.h>
#include <softopt/physics/material.h>
#include <softopt/solvers/cell_matrix_scatter.h>
#include <softopt/solvers/direct_solver.h>

#include <map>
#include <memory>
#include <string>
#include <typeindex>

namespace softopt
{
  /**
   * Finite strain, nearly incompressible hyperelasticity with a follower
   * cavity pressure (Eqs. deltaW01, res, LinMat, statCond0-2 and the
   * appendix), on quadratic tetrahedra with an element-wise constant
   * pressure: FESystem(FE_SimplexP<3>(2)^3, FE_SimplexDGP<3>(0)).
   *
   * The state a = [u, p~] holds both fields. The element pressure is
   * condensed out per cell: assemble() returns the condensed residual
   * r^e = r_u^e - K_up^e (K_pp^e)^{-1} r_p^e and tangent
   * K^e = K_uu^e - K_up^e (K_pp^e)^{-1} K_pu^e (Eq. statCond2), the global
   * system carries the pressure DoFs as decoupled identity rows, and update()
   * recovers dp~^e from du^e by Eq. statCond1. (Solving r_p = 0 exactly for
   * p~(u) instead gives the same solution but a penalty-like Newton
   * iteration that copes badly with K >> G.)
   *
   * The class runs on whatever mapping it is handed (MappingFE for the mesh
   * as read, MappingFEField for a shape-optimized design) and knows nothing
   * of shapes. Units: mm, N, MPa.
   */
  class HyperelasticProblem : public EquilibriumProblem
  {
  public:
    /**
     * @p pressure is the cavity pressure at load factor 1, in MPa.
     * The triangulation, mapping, geometry and material must outlive this.
     */
    HyperelasticProblem(const Triangulation<3> &triangulation,
                        const Mapping<3>       &mapping,
                        const Geometry         &geometry,
                        const Material  &material,
                        const double            pressure);

    /** Distributes DoFs, builds the constraints and the matrix. */
    void
    setup_system();

    Vector
    create_vector() const override;

    void
    assemble(const Vector &a,
             const double  load_factor,
             Vector       &residual,
             Vector       &load,
             const bool    with_tangent) override;

    void
    factorize() override;

    void
    solve(const Vector &b, Vector &x) const override;

    unsigned int
    n_negative_pivots() const override;

    void
    update(Vector &a, const Vector &du) const override;

    /** Zeroes the element pressures of @p v. */
    void
    zero_condensed(Vector &v) const override;

    /** A fresh factorization, or with "kept factorization" GMRES on the one
     * held (DirectSolver::solve_krylov). */
    void
    solve_tangent(const Vector &b, Vector &x) override;

    /** GMRES on the factorization held, to the GMRES tolerance of
     * subsection "Linear solver" (it factorizes if GMRES does not converge
     * within its iterations). */
    void
    solve_nearby_tangent(const Vector &b, Vector &x) override;

    /** x = K^{-1} b for the tangent of the last assemble() by GMRES on the
     * factorization held, to 1e-10 relative residual (about the accuracy
     * of a direct solve at nu = 0.4999): the adjoints. */
    void
    solve_kept(const Vector &b, Vector &x);

    /** subsection "Linear solver" (default: every Newton step factorizes). */
    void
    set_linear_solver(const DirectSolver::Parameters &parameters);

    /** The tangent of the last assemble() (for tests and adjoints). */
    const PETScWrappers::MPI::SparseMatrix &
    tangent() const;

    /** Sets the element pressures of @p a to p~(u), which makes r_p = 0. */
    void
    store_pressure(Vector &a) const;

    /**
     * Smallest J over all quadrature points, and its position in the
     * reference configuration (for messages about inverted elements).
     */
    double
    min_jacobian(const Vector &a) const;

    /**
     * Writes displacement, condensed pressure p~ (MPa), cell mean J and
     * cell mean Cauchy stress (MPa) to directory/name_NNNN.vtu (with a .pvtu
     * record under MPI) and returns the file name to list in a .pvd.
     */
    std::string
    write_vtu(const Vector       &a,
              const std::string &directory,
              const std::string &name,
              const unsigned int counter) const;

    const DoFHandler<3> &
    get_dof_handler() const;

    const Mapping<3> &
    get_mapping() const;

    const FESystem<3> &
    get_fe() const;

    const Material &
    get_material() const;

    const Geometry &
    get_geometry() const;

    /** The cavity pressure at load factor 1, in MPa. */
    double
    get_pressure() const;

    /** Volume quadrature (6 points, degree 3) and face quadrature (7 points,
     * degree 5: exact for the P2 follower load and cavity volume). */
    const Quadrature<3> &
    cell_quadrature() const;
    const Quadrature<2> &
    face_quadrature() const;

    /** The Dirichlet constraints (homogeneous). */
    const AffineConstraints<double> &
    get_constraints() const;

    /** A ghosted copy of @p a for reading values on locally owned cells. */
    Vector
    ghosted(const Vector &a) const;

    MPI_Comm
    get_communicator() const;

    /** Calls and wall time of the expensive phases, for progress reports
     * and benchmarks. */
    struct Statistics
    {
      /** Assemblies with the tangent; residual-only ones are n_residuals. */
      unsigned int n_assemblies      = 0;
      unsigned int n_factorizations  = 0;
      unsigned int n_solves          = 0;
      unsigned int n_residuals       = 0;
      /** GMRES iterations on kept factorizations (each one solve with
       * it; flexible GMRES forms the solution without another). */
      unsigned int n_krylov_iterations = 0;
      double       assembly_time      = 0;
      double       factorization_time = 0;
      double       solve_time         = 0;
      double       residual_time      = 0;

      /** "N assemblies T s, N factorizations T s, N solves T s, N
       * residuals T s, N GMRES iterations" (scripts/bench_iteration reads
       * it). */
      std::string
      summary() const;

      /** Adds @p other's counts and times (the physics of an earlier mesh
       * of the run). */
      Statistics &
      operator+=(const Statistics &other);
    };

    const Statistics &
    get_statistics() const;

    /**
     * The object of type T kept with this problem, made by @p make (a
     * callable returning std::unique_ptr<T>) on the first call: work that
     * a functional would otherwise repeat for every design on the same mesh
     * and DoFs, such as softening's second tangent. It lives as long as the
     * problem, so it never outlives the mesh it was built on (a remesh
     * builds a new problem).
     */
    template <typename T, typename Make>
    T &
    companion(const Make &make) const
    {
      std::shared_ptr<void> &slot = companions[std::type_index(typeid(T))];
      if (!slot)
        slot = std::shared_ptr<T>(make());
      return *static_cast<T *>(slot.get());
    }

  private:
    /** GMRES on the kept factorization (DirectSolver::solve_krylov). */
    void
    solve_krylov(const Vector      &b,
                 Vector            &x,
                 const double       tolerance,
                 const unsigned int max_iterations);

    /** Adds cell @p cell's matrix (if not null) and vectors to the global
     * ones, dropping constrained rows and columns. */
    void
    add_to_global(unsigned int                                       cell,
                  const FullMatrix<double>                          *cell_matrix,
                  const std::vector<const dealii::Vector<double> *> &cell_vectors,
                  const std::vector<types::global_dof_index>        &dof_indices,
                  const std::vector<Vector *>                       &vectors);

    MPI_Comm                triangulation_comm;
    const Triangulation<3> &triangulation;
    const Mapping<3>       &mapping;
    const Geometry         &geometry;
    const Material  &material;
    const double            pressure;

    FESystem<3>           fe;
    DoFHandler<3>         dof_handler;
    QGaussSimplex<3>      quadrature;
    QGaussSimplex<2>      quadrature_face;
    IndexSet              locally_owned_dofs;
    IndexSet              locally_relevant_dofs;
    IndexSet              pressure_dofs;
    AffineConstraints<double> constraints;

    /** Per locally owned cell, from the last assemble(): r_p^e, the
     * coupling b^e = -K_up^e and |Omega^e|, for update(). */
    std::vector<double>                 cell_pressure_residual;
    std::vector<dealii::Vector<double>> cell_coupling;
    std::vector<double>                 cell_volume;

    PETScWrappers::MPI::SparseMatrix system_matrix;
    CellMatrixScatter                scatter;
    /** The condensed pressure's diagonal entries of the assembly under
     * way: added after the scatter's displacement blocks. */
    std::vector<std::pair<PetscInt, double>> pressure_diagonal;
    DirectSolver                     direct_solver;
    DirectSolver::Parameters         linear_solver;

    mutable Statistics statistics;

    /** companion(); the last member, so destroyed before the DoFs. */
    mutable std::map<std::type_index, std::shared_ptr<void>> companions;
  };
} // namespace softopt

#endif
