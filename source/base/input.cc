#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <softopt/base/input.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace softopt
{
  InputFile::InputFile(const std::string &path)
    : file_path(path)
  {
    std::ifstream in(path);
    AssertThrow(in.good(),
                ExcMessage("Cannot read the parameter file <" + path +
                           ">: it does not exist or is not readable."));
    // A file with nothing but blanks and comments would run the defaults'
    // case, whose mesh is relative to the file: say what is wrong instead.
    bool        sets_something = false;
    std::string line;
    while (!sets_something && std::getline(in, line))
      {
        const std::string text = Utilities::trim(line.substr(0, line.find('#')));
        sets_something         = text.rfind("set ", 0) == 0;
      }
    AssertThrow(sets_something,
                ExcMessage("The parameter file <" + path +
                           "> is empty: it sets no entry. Start from one of "
                           "the files in prm/ (doc/parameters.md lists every "
                           "entry)."));
    folder = std::filesystem::absolute(path).parent_path().string();
  }



  InputFile
  InputFile::in_code(const std::string &description)
  {
    InputFile input;
    input.file_path = description;
    input.folder    = std::filesystem::current_path().string();
    return input;
  }



  const std::string &
  InputFile::path() const
  {
    return file_path;
  }



  std::string
  InputFile::resolve(const std::string &relative) const
  {
    const std::filesystem::path p(relative);
    if (p.is_absolute())
      return p.string();
    return (std::filesystem::path(folder) / p).lexically_normal().string();
  }



  std::vector<unsigned int>
  InputFile::numbered_subsections(const std::string &prefix) const
  {
    // Only top-level subsections count: track the nesting depth.
    std::ifstream     in(file_path);
    const std::regex  pattern("^\\s*subsection\\s+" + prefix +
                             "\\s+([0-9]+)\\s*(#.*)?$");
    std::set<unsigned int> numbers;
    int               depth = 0;
    std::string       line;
    while (std::getline(in, line))
      {
        std::smatch match;
        const std::string trimmed = Utilities::trim(line);
        if (depth == 0 && std::regex_match(line, match, pattern))
          numbers.insert(std::stoul(match[1]));
        if (trimmed.rfind("subsection", 0) == 0)
          ++depth;
        else if (trimmed == "end" || trimmed.rfind("end ", 0) == 0 ||
                 trimmed.rfind("end#", 0) == 0)
          --depth;
      }
    return {numbers.begin(), numbers.end()};
  }



  std::string
  InputFile::where(const std::string &subsection, const std::string &entry) const
  {
    std::string w = "<" + file_path + ">";
    if (!subsection.empty())
      w += ", subsection \"" + subsection + "\"";
    w += ", entry \"" + entry + "\"";
    return w;
  }



  std::vector<types::boundary_id>
  parse_boundary_ids(const std::string &text, const std::string &where)
  {
    std::vector<types::boundary_id> ids;
    for (const auto &item : Utilities::split_string_list(text, ','))
      {
        AssertThrow(Patterns::Integer(0, 254).match(item),
                    ExcMessage(where + ": \"" + item +
                               "\" is not a boundary id (an integer from 0 "
                               "to 254)."));
        ids.push_back(static_cast<types::boundary_id>(std::stoi(item)));
      }
    return ids;
  }



  std::map<types::boundary_id, std::array<bool, 3>>
  parse_dirichlet_boundaries(const std::string &text, const std::string &where)
  {
    std::map<types::boundary_id, std::array<bool, 3>> result;
    for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        const auto parts = Utilities::split_string_list(item, ':');
        AssertThrow(parts.size() == 2,
                    ExcMessage(where + ": \"" + item +
                               "\" is not of the form \"id: components\", "
                               "for example \"1: xyz\"."));
        const auto ids = parse_boundary_ids(parts[0], where);
        AssertThrow(ids.size() == 1,
                    ExcMessage(where + ": \"" + item +
                               "\" names more than one boundary id."));
        std::array<bool, 3> fixed{{false, false, false}};
        AssertThrow(!parts[1].empty(),
                    ExcMessage(where + ": boundary " + parts[0] +
                               " fixes no component."));
        for (const char c : parts[1])
          {
            AssertThrow(c == 'x' || c == 'y' || c == 'z',
                        ExcMessage(where + ": \"" + parts[1] +
                                   "\" may only contain x, y and z."));
            fixed[c - 'x'] = true;
          }
        AssertThrow(result.count(ids[0]) == 0,
                    ExcMessage(where + ": boundary " + parts[0] +
                               " appears twice."));
        result[ids[0]] = fixed;
      }
    return result;
  }



  std::vector<double>
  parse_doubles(const std::string &text, const std::string &where)
  {
    std::vector<double> values;
    for (const auto &item : Utilities::split_string_list(text, ','))
      {
        AssertThrow(Patterns::Double().match(item),
                    ExcMessage(where + ": \"" + item + "\" is not a number."));
        values.push_back(Utilities::string_to_double(item));
      }
    return values;
  }



  Tensor<1, 3>
  parse_vector(const std::string &text, const std::string &where)
  {
    const auto values = parse_doubles(text, where);
    AssertThrow(values.size() == 3,
                ExcMessage(where + ": \"" + text +
                           "\" must be three comma-separated numbers, for "
                           "example \"1, 0, 0\"."));
    return Tensor<1, 3>({values[0], values[1], values[2]});
  }



  Patterns::List
  vector_pattern()
  {
    return Patterns::List(Patterns::Double(), 3, 3, ",");
  }



  std::vector<NamedPoint>
  parse_named_points(const std::string &text, const std::string &where)
  {
    const std::regex        valid_name("[A-Za-z0-9_-]+");
    std::vector<NamedPoint> points;
    for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        const auto colon = item.find(':');
        AssertThrow(colon != std::string::npos,
                    ExcMessage(where + ": \"" + item +
                               "\" is not of the form \"name: x, y, z\", "
                               "for example \"tip: 60, 0, 11.5\"."));
        const std::string name = Utilities::trim(item.substr(0, colon));
        AssertThrow(!name.empty(),
                    ExcMessage(where + ": \"" + item +
                               "\" has no name before the colon; write "
                               "\"name: x, y, z\", for example \"tip: 60, "
                               "0, 11.5\"."));
        AssertThrow(std::regex_match(name, valid_name),
                    ExcMessage(where + ": the name \"" + name +
                               "\" may only contain letters, digits, '_' "
                               "and '-' (it becomes a CSV column name)."));
        for (const auto &p : points)
          AssertThrow(p.name != name,
                      ExcMessage(where + ": the name \"" + name +
                                 "\" appears twice."));
        const Tensor<1, 3> x =
          parse_vector(Utilities::trim(item.substr(colon + 1)),
                       where + ", point \"" + name + "\"");
        points.push_back({name, Point<3>(x)});
      }
    return points;
  }
} // namespace softopt
