#ifndef softopt_optimization_mma_h
#define softopt_optimization_mma_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <iosfwd>
#include <vector>

namespace softopt
{
  /**
   * Svanberg's Method of Moving Asymptotes (MMA; Svanberg 1987, in the form
   * of the notes "MMA and GCMMA - two methods for nonlinear optimization",
   * 2007) for the problem
   *
   *   min  f_0(x) + a_0 z + sum_i (c_i y_i + 0.5 d_i y_i^2)
   *   s.t. f_i(x) - a_i z - y_i <= 0,  i = 1..m,
   *        xmin <= x <= xmax,  y >= 0,  z >= 0.
   *
   * Each row i is either
   * - RowType::objective (a_i = 1): the min-max form "minimize z subject to
   *   g_i(x) - z <= 0", which minimizes max_i g_i(x), with f_0 = 0; or
   * - RowType::constraint (a_i = 0): an ordinary constraint f_i(x) <= 0.
   * With constraint rows only, f_0 is the objective (the ordinary form).
   * In both cases a_0 = 1, and the c_i are large (Settings::c), so that the
   * elastic variables y_i vanish at a feasible solution. As z >= 0, the
   * min-max form needs objective rows that are positive (or shifted to be)
   * and, like the constraints, scaled to order 1 against c_i.
   *
   * The class knows only vectors: the design vector x may be distributed
   * over the ranks of an MPI communicator, each rank passing its locally
   * owned entries; every sum over the design variables in the primal-dual
   * interior-point solution of the subproblem ("subsolv") is an
   * MPI_Allreduce, and every decision there depends on reduced values
   * only, so all ranks take the same path. The number of rows m is small,
   * and the row values are global (the same on every rank).
   */
  class MMA
  {
  public:
    /** The role of one row f_i: its coefficient a_i of z. */
    enum class RowType
    {
      /** a_i = 1: a term g_i of the maximum that is minimized. */
      objective,
      /** a_i = 0: an ordinary constraint f_i(x) <= 0. */
      constraint
    };

    /** The parameters of mmasub and subsolv. */
    struct Settings
    {
      /** Move limit as a fraction of xmax - xmin. */
      double move_limit = 0.5;
      /** asyinit: initial distance of the asymptotes, times xmax - xmin. */
      double asymptote_init = 0.5;
      /** asydecr: shrink factor of the asymptotes when x oscillates. */
      double asymptote_decrease = 0.7;
      /** asyincr: growth factor of the asymptotes when x moves steadily. */
      double asymptote_increase = 1.2;
      /** c_i, the linear cost of the elastic variables y_i. */
      double c = 1000;
      /** d_i, the quadratic cost of the elastic variables y_i. */
      double d = 1;
      /** a_0, the cost of z. */
      double a0 = 1;
      /** epsimin: the smallest barrier parameter of subsolv. */
      double subproblem_tolerance = 1e-7;
    };

    /**
     * Sets up MMA for @p n_local locally owned design variables and one row
     * per entry of @p row_types, with default Settings.
     */
    MMA(const unsigned int          n_local,
        const std::vector<RowType> &row_types,
        const MPI_Comm              comm);

    /** As above, with the given @p settings. */
    MMA(const unsigned int          n_local,
        const std::vector<RowType> &row_types,
        const MPI_Comm              comm,
        const Settings             &settings);

    /**
     * One MMA iteration: builds the convex approximation at @p x (the local
     * part of x^k) from the values and gradients, solves it, and overwrites
     * @p x with x^{k+1}. @p f0 and @p df0 are the objective f_0 and its
     * gradient (pass 0 and an empty view in the min-max form); @p f holds
     * the m row values f_i(x^k) (global), @p df their gradients (local
     * parts); @p xmin and @p xmax are the box bounds (local parts), with
     * xmin < xmax and x inside. Collective: call it on every rank.
     */
    void
    update(const dealii::ArrayView<double>                    &x,
           const double                                        f0,
           const dealii::ArrayView<const double>              &df0,
           const std::vector<double>                          &f,
           const std::vector<dealii::ArrayView<const double>> &df,
           const dealii::ArrayView<const double>              &xmin,
           const dealii::ArrayView<const double>              &xmax);

    /** The number of completed iterations (calls of update()). */
    unsigned int
    n_iterations() const
    {
      return iteration;
    }

    /** max_j |x^{k+1}_j - x^k_j| over all ranks in the last update(). */
    double
    last_step() const
    {
      return step;
    }

    /** z of the last subproblem solution (the approximate maximum). */
    double
    get_z() const
    {
      return solution.z;
    }

    /** y_i of the last subproblem solution (nonzero: row i infeasible). */
    const std::vector<double> &
    get_y() const
    {
      return solution.y;
    }

    /** The multipliers lambda_i of the rows in the last subproblem. */
    const std::vector<double> &
    get_lambda() const
    {
      return solution.lam;
    }

    /**
     * Writes the state that an exact restart needs (iteration count,
     * x^{k-1}, x^{k-2}, and the asymptotes low and upp; this rank's part)
     * to @p out in binary form.
     */
    void
    save(std::ostream &out) const;

    /**
     * Reads a state written by save() on the same rank with the same
     * number of local variables and rows; the next update() then produces
     * the same iterate as the object that was saved.
     */
    void
    load(std::istream &in);

  private:
    /** A point of the subproblem's primal-dual interior-point method. */
    struct Iterate
    {
      std::vector<double> x, xsi, eta;   // local: x, multipliers of alpha, beta
      std::vector<double> y, lam, mu, s; // rows: y, lambda, mu_i, slacks
      double              z = 0, zeta = 0;
    };

    /** mmasub's asymptote update: initial, then by x's oscillation. */
    void
    update_asymptotes(const dealii::ArrayView<const double> &x,
                      const dealii::ArrayView<const double> &xmin,
                      const dealii::ArrayView<const double> &xmax);

    /** subsolv: solves the subproblem at the current approximation. */
    void
    solve_subproblem();

    /** The 2-norm (returned) and max norm of the relaxed KKT residual. */
    double
    residual_norm(const Iterate &v,
                  const double   epsilon,
                  double        &max_abs) const;

    /** The Newton direction dv for the relaxed KKT conditions at v. */
    void
    newton_direction(const Iterate &v, const double epsilon, Iterate &dv) const;

    /** The largest step (<= 1) from v along dv keeping v interior. */
    double
    step_length(const Iterate &v, const Iterate &dv) const;

    unsigned int        n; // locally owned design variables
    unsigned int        m; // rows
    MPI_Comm            comm;
    Settings            settings;
    std::vector<double> a, c, d; // a_i, c_i, d_i of the problem

    // The state of the iteration: k, x^{k-1}, x^{k-2}, asymptotes L, U.
    unsigned int        iteration = 0;
    double              step      = 0;
    std::vector<double> x_old1, x_old2, low, upp;

    // The current subproblem (Svanberg's notation): bounds alpha, beta,
    // approximation coefficients p_0j, q_0j, p_ij, q_ij, right sides b_i.
    std::vector<double>              alpha, beta, p0, q0, b;
    std::vector<std::vector<double>> p, q;
    Iterate                          solution;
  };
} // namespace softopt

#endif
