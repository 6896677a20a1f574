#ifndef softopt_base_on_rank_zero_h
#define softopt_base_on_rank_zero_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <sstream>
#include <string>

namespace softopt
{
  /** The message of @p e for the user: a deal.II exception's own text
   * (without the file, line and function of the throw), else what(). */
  inline std::string
  user_message(const std::exception &e)
  {
    if (const auto *deal = dynamic_cast<const dealii::ExceptionBase *>(&e))
      {
        std::ostringstream message;
        deal->print_info(message);
        return dealii::Utilities::trim(message.str());
      }
    return e.what();
  }

  /**
   * Runs @p work on rank 0 only (a file written, a serial geometry
   * computation) and, if it throws, throws the same message on every rank
   * of @p comm, so that all leave together. Collective.
   */
  template <typename Work>
  void
  on_rank_zero(const MPI_Comm comm, Work &&work)
  {
    std::string error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          work();
        }
      catch (const std::exception &e)
        {
          error = user_message(e);
        }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(), dealii::ExcMessage(error));
  }
} // namespace softopt

#endif
