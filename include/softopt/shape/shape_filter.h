#ifndef softopt_shape_shape_filter_h
#define softopt_shape_shape_filter_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <softopt/base/input.h>
#include <softopt/geometry/geometry.h>
#include <softopt/shape/design_configuration.h>
#include <softopt/solvers/cell_matrix_scatter.h>
#include <softopt/solvers/direct_solver.h>

namespace softopt
{
  /**
   * The nonlinear PDE filter of Section 3: the shape field psi minimizes
   *   Pi_psi(psi; d) = 1/2 int W_psi(F_psi) dV + 1/(2|Omega_o|) int |psi - d|^2 dV
   * over the initial design Omega_o (Eq. PDEpot01, with W_psi of Eq. Wshape),
   * with psi = 0 on the shape-fixed boundaries. Its stationarity,
   *   r_psi = 1/2 int P_psi : grad dpsi dV + 1/|Omega_o| int (psi - d) . dpsi dV,
   * is Eq. PDEpot02 derived from the potential (the coupling is the volume
   * integral over Omega_o scaled by 1/|Omega_o|, not the surface integral
   * of Eq. PDE04, which contradicts the potential; see doc/theory.md).
   * Solved by modified Newton on a MUMPS factorization kept between
   * solves and used for the adjoint.
   */
  class ShapeFilter
  {
  public:
    using Vector = PETScWrappers::MPI::Vector;

    /** Subsection "Shape filter". */
    struct Parameters
    {
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm, const InputFile &input);

      /** K_psi and G_psi in mm^-1, k_psi dimensionless (Eq. Wshape). */
      double K_psi = 1e-5, G_psi = 1e-2, k_psi = 10;

      /** Boundaries where psi = 0 (empty: every Dirichlet and design
       * boundary, the paper's choice). */
      std::vector<types::boundary_id> fixed_boundary_ids;
    };

    explicit ShapeFilter(const Parameters &parameters);

    /**
     * Builds the constraints, matrices and |Omega_o| on @p design; call again
     * after a mesh update (Omega_o changes). @p design must outlive this.
     */
    void
    setup(const DesignConfiguration &design, const Geometry &geometry);

    /** What a filter solve reports: Newton iterations and the health of
     * the shape it produced. */
    struct Result
    {
      unsigned int iterations = 0;
      /** The smallest J_psi = det(I + grad psi) at a quadrature point. */
      double min_J_psi = 1;
      /** The worst mean-ratio quality of the tetrahedra of X = X_o + psi
       * through their corner nodes (1: equilateral, <= 0: inverted). */
      double worst_quality = 1;
      /** The centroid of that tetrahedron in X, in mm. */
      Point<3> worst_element;
    };

    /**
     * psi(d) by Newton from the given @p psi. Throws a message if the shape
     * inverts an element (J_psi <= 0 or det(dX/dxi) <= 0); such a shape
     * never reaches the physics.
     */
    Result
    solve(const Vector &d, Vector &psi);

    /** Drops the kept factorization (it may be of a refused shape, or
     * failed); the next solve factorizes anew. */
    void
    forget_factorization();

    /** Takes the physics' linear solver settings after setup(): whether the
     * filter's factors go on disk (MUMPS' ICNTL(22)) is decided by the same
     * rule and this mesh's cell count, from the next factorization on. On a
     * fine mesh they are as large as the physics' (three quadratic
     * components on the same nodes). */
    void
    set_linear_solver(const DirectSolver::Parameters &parameters);

    /** Solves (dr_psi/dpsi)^T mu = @p rhs at the last solution (the tangent
     * is symmetric), by GMRES on the kept factorization. */
    void
    solve_adjoint(const Vector &rhs, Vector &mu);

    /** -mu^T dr_psi/dd = M mu / |Omega_o| (Eq. sens06). */
    Vector
    design_gradient(const Vector &mu) const;

    /** r_psi(psi; d); with @p with_tangent also dr_psi/dpsi (tangent()). */
    Vector
    residual(const Vector &d, const Vector &psi, const bool with_tangent);

    const PETScWrappers::MPI::SparseMatrix &
    tangent() const;

    const AffineConstraints<double> &
    get_constraints() const;

    /** |Omega_o| in mm^3. */
    double
    initial_volume() const;

    /** The health (J_psi, element quality) of the shape X_o + @p psi. */
    Result
    mesh_health(const Vector &psi) const;

  private:

    /** The quadrature of every cell integral of the filter. */
    static const QGaussSimplex<3> &
    quadrature();

    /**
     * What the filter's loops need of a locally owned cell, found once per
     * mesh by setup(): JxW and the gradients of the ten scalar P2 shape
     * functions on Omega_o (fixed between mesh updates; the MappingFEField
     * on X_o costs about 40 % of a residual otherwise), and where the
     * cell's DoFs are (deal.II's and PETSc's look-ups per cell cost as
     * much as a residual's arithmetic).
     */
    struct CellData
    {
      std::vector<double>       JxW;
      std::vector<Tensor<1, 3>> grad; // [q * 10 + scalar function]
      /** PETSc rows of the DoFs, -1 where psi is fixed (petsc_rows). */
      std::vector<PetscInt> rows;
      /** Positions of the DoFs in a ghosted vector's local form: the
       * locally owned entries, then the ghosts (LocalEntries). */
      std::vector<unsigned int> local;
      /** The cell's active_cell_index(), CellMatrixScatter's key. */
      unsigned int active_index;
    };

    /** grad v at quadrature point @p q of a cell from its DoF values. */
    Tensor<2, 3>
    gradient(const CellData &cell, const unsigned int q, const std::vector<double> &v) const;

    /** v at quadrature point @p q of a cell from its DoF values. */
    Tensor<1, 3>
    value(const unsigned int q, const std::vector<double> &v) const;

    /** Per locally owned cell. */
    std::vector<CellData> cells;
    /** The scalar shape functions' values [q][function], the same on every
     * cell. */
    std::vector<std::vector<double>> shape_values;
    /** For each vector DoF of a cell: its component and scalar function. */
    std::vector<std::pair<unsigned int, unsigned int>> component_function;

    const Parameters                 parameters;
    const DesignConfiguration       *design = nullptr;
    AffineConstraints<double>        constraints;
    PETScWrappers::MPI::SparseMatrix matrix;
    CellMatrixScatter                scatter;
    PETScWrappers::MPI::SparseMatrix mass_matrix;
    std::unique_ptr<DirectSolver>    solver;
    bool                             out_of_core = false;
    /** (d, psi) of the last solve() while its tangent is not assembled. */
    std::unique_ptr<std::pair<Vector, Vector>> solution;
    double                           volume                 = 0;
  };
} // namespace softopt

#endif
