#ifndef softopt_io_parameter_differences_h
#define softopt_io_parameter_differences_h

#include <deal.II/base/parameter_handler.h>

#include <set>
#include <string>
#include <vector>

namespace softopt
{
  /**
   * The entries whose values differ between the parameter file a run
   * wrote (parameters.prm, every entry as used: OutputDirectory::
   * write_parameters) and @p now, each as "Subsection/Entry: <then> then,
   * <now> now"; entries named in @p may_change ("Subsection/Entry", or
   * "Subsection/" followed by a star for a whole subsection) are not
   * compared. An entry the written file lacks (declared since) differs
   * only if it is set to other than its default now, the value the older
   * program acted with. Values are compared word by word, numbers by
   * value.
   */
  std::vector<std::string>
  parameter_differences(const std::string                &written_file,
                        const dealii::ParameterHandler   &now,
                        const std::set<std::string>      &may_change);
} // namespace softopt

#endif
