#include <deal.II/base/exceptions.h>

#include <softopt/optimization/mma.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <istream>
#include <ostream>
#include <string>

namespace softopt
{
  namespace
  {
    // Svanberg's fixed constants of mmasub: albefa keeps alpha, beta a tenth
    // of the way away from the asymptotes; raa0 makes the approximation
    // strictly convex; xmamieps is a lower bound on xmax - xmin.
    constexpr double albefa   = 0.1;
    constexpr double raa0     = 1e-5;
    constexpr double xmamieps = 1e-5;

    /** Solves the small dense system A u = r (row-major, size k) in place
     * by Gaussian elimination with partial pivoting; r becomes u. */
    void
    solve_dense(std::vector<double> &A, std::vector<double> &r)
    {
      const unsigned int k = r.size();
      for (unsigned int col = 0; col < k; ++col)
        {
          unsigned int pivot = col;
          for (unsigned int i = col + 1; i < k; ++i)
            if (std::abs(A[i * k + col]) > std::abs(A[pivot * k + col]))
              pivot = i;
          AssertThrow(A[pivot * k + col] != 0.,
                      dealii::ExcMessage("MMA: singular subproblem system."));
          if (pivot != col)
            {
              for (unsigned int j = 0; j < k; ++j)
                std::swap(A[col * k + j], A[pivot * k + j]);
              std::swap(r[col], r[pivot]);
            }
          for (unsigned int i = col + 1; i < k; ++i)
            {
              const double factor = A[i * k + col] / A[col * k + col];
              for (unsigned int j = col; j < k; ++j)
                A[i * k + j] -= factor * A[col * k + j];
              r[i] -= factor * r[col];
            }
        }
      for (unsigned int i = k; i-- > 0;)
        {
          for (unsigned int j = i + 1; j < k; ++j)
            r[i] -= A[i * k + j] * r[j];
          r[i] /= A[i * k + i];
        }
    }

    /** v + t dv, entry by entry. */
    void
    add_scaled(std::vector<double>       &out,
               const std::vector<double> &v,
               const double               t,
               const std::vector<double> &dv)
    {
      out.resize(v.size());
      for (unsigned int i = 0; i < v.size(); ++i)
        out[i] = v[i] + t * dv[i];
    }
  } // namespace



  MMA::MMA(const unsigned int          n_local,
           const std::vector<RowType> &row_types,
           const MPI_Comm              comm)
    : MMA(n_local, row_types, comm, Settings())
  {}



  MMA::MMA(const unsigned int          n_local,
           const std::vector<RowType> &row_types,
           const MPI_Comm              comm,
           const Settings             &settings)
    : n(n_local)
    , m(row_types.size())
    , comm(comm)
    , settings(settings)
    , a(m)
    , c(m, settings.c)
    , d(m, settings.d)
    , x_old1(n)
    , x_old2(n)
    , low(n)
    , upp(n)
  {
    for (unsigned int i = 0; i < m; ++i)
      a[i] = (row_types[i] == RowType::objective ? 1. : 0.);
  }



  void
  MMA::update_asymptotes(const dealii::ArrayView<const double> &x,
                         const dealii::ArrayView<const double> &xmin,
                         const dealii::ArrayView<const double> &xmax)
  {
    for (unsigned int j = 0; j < n; ++j)
      {
        const double range = xmax[j] - xmin[j];
        if (iteration < 2)
          {
            // The first two iterations: asymptotes at x -/+ asyinit (xmax -
            // xmin), as there is no history to judge oscillation from.
            low[j] = x[j] - settings.asymptote_init * range;
            upp[j] = x[j] + settings.asymptote_init * range;
          }
        else
          {
            // Svanberg's rule: if x_j oscillates (x^k - x^{k-1} and x^{k-1}
            // - x^{k-2} of opposite sign) move the asymptotes closer to
            // x_j for a more conservative approximation; if it moves
            // steadily, move them further away.
            const double sign   = (x[j] - x_old1[j]) * (x_old1[j] - x_old2[j]);
            const double factor = sign > 0 ? settings.asymptote_increase :
                                  sign < 0 ? settings.asymptote_decrease :
                                             1.;
            low[j]              = x[j] - factor * (x_old1[j] - low[j]);
            upp[j]              = x[j] + factor * (upp[j] - x_old1[j]);
            // Keep the asymptotes between 0.01 and 10 times xmax - xmin
            // from x_j.
            low[j] = std::min(std::max(low[j], x[j] - 10. * range),
                              x[j] - 0.01 * range);
            upp[j] = std::max(std::min(upp[j], x[j] + 10. * range),
                              x[j] + 0.01 * range);
          }
      }
  }



  void
  MMA::update(const dealii::ArrayView<double>                    &x,
              const double                                        f0,
              const dealii::ArrayView<const double>              &df0,
              const std::vector<double>                          &f,
              const std::vector<dealii::ArrayView<const double>> &df,
              const dealii::ArrayView<const double>              &xmin,
              const dealii::ArrayView<const double>              &xmax)
  {
    (void)f0; // a constant of the subproblem
    AssertDimension(x.size(), n);
    AssertDimension(xmin.size(), n);
    AssertDimension(xmax.size(), n);
    AssertDimension(f.size(), m);
    AssertDimension(df.size(), m);
    Assert(df0.size() == n || df0.size() == 0,
           dealii::ExcDimensionMismatch(df0.size(), n));
    for (unsigned int i = 0; i < m; ++i)
      AssertDimension(df[i].size(), n);
    for (unsigned int j = 0; j < n; ++j)
      Assert(xmin[j] <= x[j] && x[j] <= xmax[j] && xmin[j] < xmax[j],
             dealii::ExcMessage("MMA: x lies outside [xmin, xmax], or "
                                "xmin = xmax (alpha = beta in subsolv)."));

    const dealii::ArrayView<const double> x_k(x.data(), n);
    update_asymptotes(x_k, xmin, xmax);

    alpha.resize(n);
    beta.resize(n);
    p0.resize(n);
    q0.resize(n);
    p.assign(m, std::vector<double>(n));
    q.assign(m, std::vector<double>(n));
    b.assign(m, 0.);
    for (unsigned int j = 0; j < n; ++j)
      {
        const double range = xmax[j] - xmin[j];
        // The bounds of the subproblem: the box, the move limit, and a
        // tenth of the distance to the asymptotes.
        alpha[j] = std::max({xmin[j],
                             x[j] - settings.move_limit * range,
                             low[j] + albefa * (x[j] - low[j])});
        beta[j]  = std::min({xmax[j],
                             x[j] + settings.move_limit * range,
                             upp[j] - albefa * (upp[j] - x[j])});

        // The MMA approximation f_i(x) ~ r_i + sum_j (p_ij / (U_j - x_j) +
        // q_ij / (x_j - L_j)), convex and with the value and gradient of f_i
        // at x^k, for
        //   p_ij = (U_j - x_j)^2 (1.001 (df_i/dx_j)^+ + 0.001 (df_i/dx_j)^-
        //          + raa0 / (xmax_j - xmin_j)),
        // q_ij = (x_j - L_j)^2 (...) with 1.001 and 0.001 swapped. The small
        // terms make the approximation strictly convex even where
        // df_i/dx_j = 0.
        const double ux   = upp[j] - x[j];
        const double xl   = x[j] - low[j];
        const double reg  = raa0 / std::max(range, xmamieps);
        auto         fill = [&](const double g, double &pj, double &qj) {
          const double plus = std::max(g, 0.), minus = std::max(-g, 0.);
          pj = ux * ux * (1.001 * plus + 0.001 * minus + reg);
          qj = xl * xl * (0.001 * plus + 1.001 * minus + reg);
        };
        fill(df0.size() > 0 ? df0[j] : 0., p0[j], q0[j]);
        for (unsigned int i = 0; i < m; ++i)
          {
            fill(df[i][j], p[i][j], q[i][j]);
            b[i] += p[i][j] / ux + q[i][j] / xl;
          }
      }
    // b_i = sum_j (p_ij / (U_j - x_j) + q_ij / (x_j - L_j)) - f_i(x^k), so
    // that the approximation of row i reads sum_j (...) - b_i <= 0.
    dealii::Utilities::MPI::sum(b, comm, b);
    for (unsigned int i = 0; i < m; ++i)
      b[i] -= f[i];

    solve_subproblem();

    double local_step = 0;
    for (unsigned int j = 0; j < n; ++j)
      {
        local_step = std::max(local_step, std::abs(solution.x[j] - x[j]));
        x_old2[j]  = x_old1[j];
        x_old1[j]  = x[j];
        x[j]       = solution.x[j];
      }
    step = dealii::Utilities::MPI::max(local_step, comm);
    ++iteration;
  }



  double
  MMA::residual_norm(const Iterate &v,
                     const double   epsilon,
                     double        &max_abs) const
  {
    // The residual of the KKT conditions of the subproblem with the
    // complementarity conditions relaxed to (...) = epsilon:
    //   dpsi/dx_j - xsi_j + eta_j,  c_i + d_i y_i - mu_i - lambda_i,
    //   a_0 - zeta - a^T lambda,  g_i(x) - a_i z - y_i + s_i - b_i,
    //   xsi_j (x_j - alpha_j) - epsilon,  eta_j (beta_j - x_j) - epsilon,
    //   mu_i y_i - epsilon,  zeta z - epsilon,  lambda_i s_i - epsilon,
    // with psi = sum_j (p_0j + lambda^T p_j) / (U_j - x_j) + (q_0j +
    // lambda^T q_j) / (x_j - L_j) and g_i = sum_j p_ij / (U_j - x_j) +
    // q_ij / (x_j - L_j). The x-parts are local, the rest global:
    // sums = [g_1, ..., g_m, |local residual|^2].
    std::vector<double> sums(m + 1, 0.);
    double              local_max = 0;
    for (unsigned int j = 0; j < n; ++j)
      {
        const double ux = upp[j] - v.x[j], xl = v.x[j] - low[j];
        double       plam = p0[j], qlam = q0[j];
        for (unsigned int i = 0; i < m; ++i)
          {
            plam += v.lam[i] * p[i][j];
            qlam += v.lam[i] * q[i][j];
            sums[i] += p[i][j] / ux + q[i][j] / xl;
          }
        const double r[3] = {plam / (ux * ux) - qlam / (xl * xl) - v.xsi[j] +
                               v.eta[j],
                             v.xsi[j] * (v.x[j] - alpha[j]) - epsilon,
                             v.eta[j] * (beta[j] - v.x[j]) - epsilon};
        for (const double ri : r)
          {
            sums[m] += ri * ri;
            local_max = std::max(local_max, std::abs(ri));
          }
      }
    dealii::Utilities::MPI::sum(sums, comm, sums);
    max_abs = dealii::Utilities::MPI::max(local_max, comm);

    double norm2 = sums[m];
    auto   add   = [&](const double r) {
      norm2 += r * r;
      max_abs = std::max(max_abs, std::abs(r));
    };
    double a_lam = 0;
    for (unsigned int i = 0; i < m; ++i)
      {
        add(c[i] + d[i] * v.y[i] - v.mu[i] - v.lam[i]);
        add(sums[i] - a[i] * v.z - v.y[i] + v.s[i] - b[i]);
        add(v.mu[i] * v.y[i] - epsilon);
        add(v.lam[i] * v.s[i] - epsilon);
        a_lam += a[i] * v.lam[i];
      }
    add(settings.a0 - v.zeta - a_lam);
    add(v.zeta * v.z - epsilon);
    return std::sqrt(norm2);
  }



  void
  MMA::newton_direction(const Iterate &v,
                        const double   epsilon,
                        Iterate       &dv) const
  {
    // The Newton step for the relaxed KKT conditions (see residual_norm()):
    // the complementarity rows give dxsi, deta, dmu, dzeta, ds in terms of
    // dx, dy, dz, dlambda; the rows in x and y give dx and dy in terms of
    // dlambda (D_x, D_y diagonal); what remains is the (m+1) x (m+1) system
    // that subsolv uses for m < n (valid for any n; here it keeps the only
    // dense system small, as n is distributed and m is small):
    //   [D_lambda + D_y^-1 + G D_x^-1 G^T   a     ] [dlambda]   [b_lambda]
    //   [a^T                               -zeta/z] [dz     ] = [delta_z ]
    // with G_ij = dg_i/dx_j, D_lambda = s / lambda, and
    //   b_lambda = delta_lambda + D_y^-1 delta_y - G D_x^-1 delta_x.
    // sums = [g_i (m), (G D_x^-1 delta_x)_i (m), (G D_x^-1 G^T)_ik (m*m)].
    std::vector<double> delx(n), diagx(n), sums(2 * m + m * m, 0.);
    std::vector<double> grad(m);
    for (unsigned int j = 0; j < n; ++j)
      {
        const double ux = upp[j] - v.x[j], xl = v.x[j] - low[j];
        const double ux2 = ux * ux, xl2 = xl * xl;
        double       plam = p0[j], qlam = q0[j];
        for (unsigned int i = 0; i < m; ++i)
          {
            plam += v.lam[i] * p[i][j];
            qlam += v.lam[i] * q[i][j];
          }
        const double dxa = v.x[j] - alpha[j], dbx = beta[j] - v.x[j];
        delx[j]  = plam / ux2 - qlam / xl2 - epsilon / dxa + epsilon / dbx;
        diagx[j] = 2. * (plam / (ux2 * ux) + qlam / (xl2 * xl)) +
                   v.xsi[j] / dxa + v.eta[j] / dbx;
        for (unsigned int i = 0; i < m; ++i)
          {
            grad[i] = p[i][j] / ux2 - q[i][j] / xl2; // G_ij = dg_i/dx_j
            sums[i] += p[i][j] / ux + q[i][j] / xl;
            sums[m + i] += grad[i] * delx[j] / diagx[j];
          }
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int k = 0; k < m; ++k)
            sums[2 * m + i * m + k] += grad[i] * grad[k] / diagx[j];
      }
    dealii::Utilities::MPI::sum(sums, comm, sums);

    std::vector<double> dely(m), diagy(m), A((m + 1) * (m + 1)), r(m + 1);
    double              delz = settings.a0 - epsilon / v.z;
    for (unsigned int i = 0; i < m; ++i)
      {
        dely[i]  = c[i] + d[i] * v.y[i] - v.lam[i] - epsilon / v.y[i];
        diagy[i] = d[i] + v.mu[i] / v.y[i];
        delz -= a[i] * v.lam[i];
        const double dellam =
          sums[i] - a[i] * v.z - v.y[i] - b[i] + epsilon / v.lam[i];
        r[i] = dellam + dely[i] / diagy[i] - sums[m + i];
        for (unsigned int k = 0; k < m; ++k)
          A[i * (m + 1) + k] = sums[2 * m + i * m + k];
        A[i * (m + 1) + i] += v.s[i] / v.lam[i] + 1. / diagy[i];
        A[i * (m + 1) + m] = a[i];
        A[m * (m + 1) + i] = a[i];
      }
    A[m * (m + 1) + m] = -v.zeta / v.z;
    r[m]               = delz;
    solve_dense(A, r);

    // Back substitution for the other unknowns, from the linearized
    // complementarity conditions.
    dv.lam.assign(r.begin(), r.begin() + m);
    dv.z = r[m];
    dv.x.resize(n);
    dv.xsi.resize(n);
    dv.eta.resize(n);
    for (unsigned int j = 0; j < n; ++j)
      {
        const double ux = upp[j] - v.x[j], xl = v.x[j] - low[j];
        double       gt_dlam = 0;
        for (unsigned int i = 0; i < m; ++i)
          gt_dlam += (p[i][j] / (ux * ux) - q[i][j] / (xl * xl)) * dv.lam[i];
        dv.x[j]          = -(delx[j] + gt_dlam) / diagx[j];
        const double dxa = v.x[j] - alpha[j], dbx = beta[j] - v.x[j];
        dv.xsi[j] = -v.xsi[j] + epsilon / dxa - v.xsi[j] * dv.x[j] / dxa;
        dv.eta[j] = -v.eta[j] + epsilon / dbx + v.eta[j] * dv.x[j] / dbx;
      }
    dv.y.resize(m);
    dv.mu.resize(m);
    dv.s.resize(m);
    for (unsigned int i = 0; i < m; ++i)
      {
        dv.y[i]  = (dv.lam[i] - dely[i]) / diagy[i];
        dv.mu[i] = -v.mu[i] + epsilon / v.y[i] - v.mu[i] * dv.y[i] / v.y[i];
        dv.s[i]  = -v.s[i] + epsilon / v.lam[i] - v.s[i] * dv.lam[i] / v.lam[i];
      }
    dv.zeta = -v.zeta + epsilon / v.z - v.zeta * dv.z / v.z;
  }



  double
  MMA::step_length(const Iterate &v, const Iterate &dv) const
  {
    // The longest step (up to 1) that keeps 1% of the distance to the
    // boundary: x inside (alpha, beta), all multipliers and slacks positive.
    double inverse = 1.;
    auto   keep    = [&inverse](const double value, const double change) {
      inverse = std::max(inverse, -1.01 * change / value);
    };
    for (unsigned int j = 0; j < n; ++j)
      {
        keep(v.x[j] - alpha[j], dv.x[j]);
        keep(beta[j] - v.x[j], -dv.x[j]);
        keep(v.xsi[j], dv.xsi[j]);
        keep(v.eta[j], dv.eta[j]);
      }
    inverse = dealii::Utilities::MPI::max(inverse, comm);
    for (unsigned int i = 0; i < m; ++i)
      {
        keep(v.y[i], dv.y[i]);
        keep(v.lam[i], dv.lam[i]);
        keep(v.mu[i], dv.mu[i]);
        keep(v.s[i], dv.s[i]);
      }
    keep(v.z, dv.z);
    keep(v.zeta, dv.zeta);
    return 1. / inverse;
  }



  void
  MMA::solve_subproblem()
  {
    // subsolv: a primal-dual interior-point method on the perturbed KKT
    // conditions, with the barrier parameter epsilon lowered from 1 by
    // factors of 10 down to epsimin; all decisions use global quantities,
    // so that every rank takes the same path.
    Iterate &v = solution;
    v.x.resize(n);
    v.xsi.resize(n);
    v.eta.resize(n);
    for (unsigned int j = 0; j < n; ++j)
      {
        v.x[j]   = 0.5 * (alpha[j] + beta[j]);
        v.xsi[j] = std::max(1., 1. / (v.x[j] - alpha[j]));
        v.eta[j] = std::max(1., 1. / (beta[j] - v.x[j]));
      }
    v.y.assign(m, 1.);
    v.lam.assign(m, 1.);
    v.s.assign(m, 1.);
    v.mu.resize(m);
    for (unsigned int i = 0; i < m; ++i)
      v.mu[i] = std::max(1., 0.5 * c[i]);
    v.z    = 1.;
    v.zeta = 1.;

    Iterate dv, trial;
    for (double epsilon = 1.; epsilon > settings.subproblem_tolerance;
         epsilon *= 0.1)
      {
        double max_abs = 0;
        double norm    = residual_norm(v, epsilon, max_abs);
        for (unsigned int it = 0; it < 200 && max_abs > 0.9 * epsilon; ++it)
          {
            newton_direction(v, epsilon, dv);
            double t = step_length(v, dv);
            // Backtracking: halve the step until the residual norm drops.
            double new_norm = 2. * norm, new_max = max_abs;
            for (unsigned int k = 0; k < 50 && new_norm > norm; ++k, t *= 0.5)
              {
                add_scaled(trial.x, v.x, t, dv.x);
                add_scaled(trial.xsi, v.xsi, t, dv.xsi);
                add_scaled(trial.eta, v.eta, t, dv.eta);
                add_scaled(trial.y, v.y, t, dv.y);
                add_scaled(trial.lam, v.lam, t, dv.lam);
                add_scaled(trial.mu, v.mu, t, dv.mu);
                add_scaled(trial.s, v.s, t, dv.s);
                trial.z    = v.z + t * dv.z;
                trial.zeta = v.zeta + t * dv.zeta;
                new_norm   = residual_norm(trial, epsilon, new_max);
              }
            std::swap(v, trial);
            norm    = new_norm;
            max_abs = new_max;
          }
      }
  }



  namespace
  {
    const char magic[] = "softopt::MMA v1";

    template <typename T>
    void
    write(std::ostream &out, const T &value)
    {
      out.write(reinterpret_cast<const char *>(&value), sizeof(T));
    }

    template <typename T>
    void
    read(std::istream &in, T &value)
    {
      in.read(reinterpret_cast<char *>(&value), sizeof(T));
    }
  } // namespace



  void
  MMA::save(std::ostream &out) const
  {
    out.write(magic, sizeof(magic));
    write(out, n);
    write(out, m);
    write(out, iteration);
    for (const auto *vector : {&x_old1, &x_old2, &low, &upp})
      out.write(reinterpret_cast<const char *>(vector->data()),
                n * sizeof(double));
    AssertThrow(out.good(), dealii::ExcMessage("MMA: cannot write state."));
  }



  void
  MMA::load(std::istream &in)
  {
    char header[sizeof(magic)];
    in.read(header, sizeof(magic));
    unsigned int n_saved = 0, m_saved = 0;
    read(in, n_saved);
    read(in, m_saved);
    AssertThrow(in.good() && std::memcmp(header, magic, sizeof(magic)) == 0,
                dealii::ExcMessage("MMA: not a saved MMA state."));
    AssertThrow(n_saved == n && m_saved == m,
                dealii::ExcMessage(
                  "MMA: the saved state has " + std::to_string(n_saved) +
                  " variables and " + std::to_string(m_saved) + " rows, not " +
                  std::to_string(n) + " and " + std::to_string(m) + "."));
    read(in, iteration);
    for (auto *vector : {&x_old1, &x_old2, &low, &upp})
      in.read(reinterpret_cast<char *>(vector->data()), n * sizeof(double));
    AssertThrow(in.good(), dealii::ExcMessage("MMA: truncated MMA state."));
  }
} // namespace softopt
