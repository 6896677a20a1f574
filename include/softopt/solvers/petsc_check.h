#ifndef softopt_solvers_petsc_check_h
#define softopt_solvers_petsc_check_h

#include <deal.II/base/exceptions.h>

#include <petscsys.h>

#include <string>

namespace softopt
{
  /** Throws, naming the PETSc call, if it returned an error code. */
  inline void
  check_petsc(const PetscErrorCode code, const char *call)
  {
    AssertThrow(code == 0,
                dealii::ExcMessage(std::string("PETSc call ") + call +
                                   " failed with error code " +
                                   std::to_string(code) + "."));
  }
} // namespace softopt

#endif
