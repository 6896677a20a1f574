#include <deal.II/base/conditional_ostream.h>

#include <softopt/base/on_rank_zero.h>
#include <softopt/app/gradient_check.h>
#include <softopt/base/seeded_random.h>
#include <softopt/io/output_directory.h>
#include <softopt/io/csv_writer.h>
#include <softopt/optimization/design_problem.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace softopt
{
  namespace
  {
    /** Functional values at d0 + step dd, NaN where the design is refused;
     * @p x (warm starts) is then that design's. */
    std::vector<double>
    values_at(DesignProblem               &problem,
              DesignIterate               &x,
              const DesignProblem::Vector &d0,
              const DesignProblem::Vector &dd,
              const double                 step,
              const ConditionalOStream    &pcout)
    {
      x.d = d0;
      x.d.add(step, dd);
      try
        {
          return problem.evaluate(x);
        }
      catch (const ExceptionBase &e)
        {
          pcout << "  the design at step " << step << " mm was refused: " << user_message(e)
                << std::endl;
          return std::vector<double>(problem.functionals().size(), std::nan(""));
        }
    }
  } // namespace



  int
  run_gradient_check(const Settings &settings, const MPI_Comm comm)
  {
    ConditionalOStream pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0);
    DesignProblem      problem(settings, comm);
    problem.add_cavity_volume();
    const auto &functionals = problem.functionals();

    DesignIterate               x         = problem.initial_iterate();
    const DesignProblem::Vector d0        = x.d;
    const std::vector<double>   values    = problem.evaluate(x);
    const auto                  gradients = problem.gradients(x);
    pcout << "Gradient check at the initial design, design scale "
          << settings.optimization.design_bound << " mm:" << std::endl;
    for (unsigned int k = 0; k < functionals.size(); ++k)
      {
        const auto &load_factors = functionals[k]->load_factors();
        pcout << "  " << functionals[k]->name() << " = " << std::setprecision(10)
              << values[k]
              << (load_factors.empty()     ? " (of the shape alone)" :
                  load_factors.size() > 1 ? " at load factors " :
                                            " at load factor ");
        for (unsigned int i = 0; i < load_factors.size(); ++i)
          pcout << (i > 0 ? ", " : "") << load_factors[i];
        pcout << std::endl;
      }

    const OutputDirectory out(settings.output_directory, comm);
    out.write_parameters(settings.prm);
    CsvWriter csv(out.file("gradient_check.csv"),
                  {"function", "direction", "h", "fd_remainder", "taylor_remainder"},
                  comm);

    DesignProblem::Vector random = problem.create_design_vector();
    for (const auto i : random.locally_owned_elements())
      random(i) = seeded_random(i);
    random.compress(VectorOperation::insert);

    const std::vector<double> steps{1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7};
    const double              scale = settings.optimization.design_bound;
    // remainders[k][direction] = (fd, taylor) per step
    std::vector<std::array<std::vector<std::pair<double, double>>, 2>> remainders(
      functionals.size());

    // Along the random direction one evaluation per step serves every
    // functional.
    std::vector<std::vector<double>> along_random;
    for (const double h : steps)
      along_random.push_back(values_at(problem, x, d0, random, h * scale, pcout));

    for (unsigned int direction = 0; direction < 2; ++direction)
      for (unsigned int k = 0; k < functionals.size(); ++k)
        {
          // The gradient direction, scaled to a largest entry of 1.
          DesignProblem::Vector dd = random;
          if (direction == 1)
            {
              dd = gradients[k];
              dd /= gradients[k].linfty_norm();
            }
          const double slope = gradients[k] * dd;
          for (unsigned int i = 0; i < steps.size(); ++i)
            {
              const double              h  = steps[i];
              const std::vector<double> at = direction == 0 ?
                                               along_random[i] :
                                               values_at(problem, x, d0, dd, h * scale, pcout);
              const double fd     = std::abs(at[k] - values[k]);
              const double taylor = std::abs(at[k] - values[k] - h * scale * slope);
              remainders[k][direction].emplace_back(fd, taylor);
              csv.add_row({functionals[k]->name(),
                           direction == 0 ? "random" : "gradient",
                           CsvWriter::format(h),
                           CsvWriter::format(fd),
                           CsvWriter::format(taylor)});
            }
        }

    pcout << "\nObserved rates of the remainders between consecutive steps "
             "(Taylor: 2 for a correct gradient, until round-off):"
          << std::endl;
    for (unsigned int k = 0; k < functionals.size(); ++k)
      for (unsigned int direction = 0; direction < 2; ++direction)
        {
          pcout << "  " << std::setw(3) << functionals[k]->name() << " "
                << std::setw(8) << (direction == 0 ? "random" : "gradient");
          const auto &r = remainders[k][direction];
          for (unsigned int i = 0; i + 1 < r.size(); ++i)
            pcout << "  " << std::fixed << std::setprecision(2)
                  << std::log10(r[i].second / r[i + 1].second);
          pcout << std::defaultfloat << std::endl;
        }

    // Verdict: the Taylor remainder falls as h^2 over three consecutive
    // steps for every function and direction.
    bool all_pass = true;
    for (const auto &per_function : remainders)
      for (const auto &r : per_function)
        {
          unsigned int run = 0, best = 0;
          for (unsigned int i = 0; i + 1 < r.size(); ++i)
            {
              run  = std::log10(r[i].second / r[i + 1].second) >= 1.9 ? run + 1 : 0;
              best = std::max(best, run);
            }
          all_pass &= best >= 3;
        }
    pcout << (all_pass ? "PASSED" : "FAILED")
          << ": the Taylor remainder falls as h^2 (rate >= 1.9) over at least "
             "three consecutive steps for every function and direction"
          << std::endl;
    return all_pass ? 0 : 1;
  }
} // namespace softopt
