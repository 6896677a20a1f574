// softopt: shape optimization of pneumatic soft actuators.
// The program only dispatches a command to the library.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <softopt/app/analysis.h>
#include <softopt/app/gradient_check.h>
#include <softopt/app/optimization.h>
#include <softopt/app/settings.h>
#include <softopt/app/verification.h>
#include <softopt/base/blas_kernels.h>

#include <algorithm>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  const char *usage =
    "Usage:\n"
    "  softopt analyze CASE.prm          inflate the design along its load path\n"
    "  softopt optimize CASE.prm         the design loop, then design.stl and the\n"
    "                                    final design's load path\n"
    "  softopt optimize CASE.prm --restart  continue from the last checkpoint\n"
    "  softopt optimize CASE.prm --start-over  remove an earlier run's\n"
    "                                    checkpoint and history, then start\n"
    "  softopt verify CASE.prm           analyze a finished run's final design on\n"
    "                                    the finer meshes of \"Mesh sizes\"\n"
    "  softopt check-design CASE.prm     castability checks (wall thickness,\n"
    "                                    self-intersection) of a run's final\n"
    "                                    design, or of the case's mesh\n"
    "  softopt mold CASE.prm             printable mold parts (two halves, cores)\n"
    "                                    of the same design, into mold/\n"
    "  softopt check-gradients CASE.prm  adjoint gradients against finite differences\n"
    "  softopt CASE.prm                  run the prm file's \"Command\"\n"
    "  softopt print-parameters          every entry, with its default and "
    "documentation\n"
    "  softopt --help                    this text and every entry\n"
    "Under MPI: mpirun -np N softopt ...\n";

  void
  print_parameters(std::ostream &out)
  {
    dealii::ParameterHandler prm;
    softopt::Settings::declare_parameters(prm, nullptr);
    prm.print_parameters(out, dealii::ParameterHandler::PRM);
  }
} // namespace



int
main(int argc, char **argv)
{
  softopt::use_the_cpus_blas_kernels(argv); // before MPI: it may start the program again
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  // --restart may stand anywhere after the command.
  std::vector<std::string> args(argv + 1, argv + argc);
  const auto flag = [&args](const std::string &name) {
    const bool given = std::find(args.begin(), args.end(), name) != args.end();
    args.erase(std::remove(args.begin(), args.end(), name), args.end());
    return given;
  };
  const bool restart    = flag("--restart");
  const bool start_over = flag("--start-over");

  try
    {
      if (args.empty() || args[0] == "--help" || args[0] == "-h")
        {
          if (root)
            {
              std::cout << usage << "\nParameters:\n\n";
              print_parameters(std::cout);
            }
          return args.empty() ? 1 : 0;
        }
      if (args[0] == "print-parameters")
        {
          if (root)
            print_parameters(std::cout);
          return 0;
        }

      std::string command, file;
      if (args[0] == "optimize")
        {
          AssertThrow(args.size() == 2,
                      dealii::ExcMessage(std::string("\"softopt optimize\" needs "
                                                     "one parameter file and "
                                                     "optionally --restart or --start-over.\n") +
                                         usage));
          command = args[0];
          file    = args[1];
        }
      else if (args[0] == "analyze" || args[0] == "check-gradients" || args[0] == "verify" ||
               args[0] == "check-design" || args[0] == "mold")
        {
          AssertThrow(args.size() == 2,
                      dealii::ExcMessage(std::string("\"softopt ") + args[0] +
                                         "\" needs one parameter file.\n" +
                                         usage));
          command = args[0];
          file    = args[1];
        }
      else
        {
          AssertThrow(args.size() == 1 && args[0].size() > 4 &&
                        args[0].substr(args[0].size() - 4) == ".prm",
                      dealii::ExcMessage("Unknown command \"" + args[0] +
                                         "\".\n" + usage));
          file = args[0];
        }

      const softopt::Settings settings(file);
      if (command.empty())
        command = settings.command;
      if (command == "check-gradients")
        return softopt::run_gradient_check(settings, MPI_COMM_WORLD);
      AssertThrow((!restart && !start_over) || command == "optimize",
                  dealii::ExcMessage(std::string(restart ? "--restart" : "--start-over") +
                                     " applies to \"optimize\" only, "
                                     "but the command is \"" + command +
                                     "\".\n" + usage));
      AssertThrow(!(restart && start_over),
                  dealii::ExcMessage(std::string("--restart and --start-over exclude each other.\n") +
                                     usage));
      if (command == "verify")
        return softopt::run_verification(settings, MPI_COMM_WORLD);
      if (command == "check-design")
        return softopt::run_check_design(settings, MPI_COMM_WORLD);
      if (command == "mold")
        return softopt::run_mold(settings, MPI_COMM_WORLD);
      if (command == "optimize")
        return softopt::run_optimization(settings,
                                         restart    ? softopt::Start::restart :
                                         start_over ? softopt::Start::start_over :
                                                      softopt::Start::fresh,
                                         MPI_COMM_WORLD);
      return softopt::run_analysis(settings, MPI_COMM_WORLD);
    }
  catch (const dealii::ExceptionBase &e)
    {
      if (root)
        {
          std::ostringstream message;
          e.print_info(message);
          std::cerr << "\nsoftopt: error: "
                    << dealii::Utilities::trim(message.str()) << std::endl;
        }
    }
  catch (const std::exception &e)
    {
      if (root)
        std::cerr << "\nsoftopt: error: " << e.what() << std::endl;
    }
  // Most errors are raised on all ranks alike; a few (a file rank 0 alone
  // writes, a rank's own checkpoint file) on one rank: abort rather than
  // leave the others waiting.
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    MPI_Abort(MPI_COMM_WORLD, 1);
  return 1;
}
