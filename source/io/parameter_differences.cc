#include <softopt/io/parameter_differences.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace softopt
{
  namespace
  {
    std::string
    trim(const std::string &s)
    {
      const auto first = s.find_first_not_of(" \t");
      const auto last  = s.find_last_not_of(" \t\r");
      return first == std::string::npos ? "" : s.substr(first, last - first + 1);
    }

    /** "Subsection/Entry" -> value of a file in ParameterHandler::PRM
     * format (comments dropped). deal.II appends "# default: ..." to a value
     * that is not its entry's default: into @p defaults, if given, goes
     * that, or else the value. */
    std::map<std::string, std::string>
    entries(std::istream &in, std::map<std::string, std::string> *defaults = nullptr)
    {
      std::map<std::string, std::string> result;
      std::vector<std::string>           path;
      for (std::string line; std::getline(in, line);)
        {
          const std::string text = trim(line);
          if (text.rfind("subsection ", 0) == 0)
            path.push_back(trim(text.substr(11)));
          else if (text == "end" && !path.empty())
            path.pop_back();
          else if (text.rfind("set ", 0) == 0)
            {
              const auto  equal = text.find('=');
              std::string key;
              for (const auto &s : path)
                key += s + "/";
              key += trim(text.substr(4, equal - 4));
              std::string value = text.substr(equal + 1);
              const auto  note  = value.rfind("# default:");
              if (defaults)
                (*defaults)[key] =
                  trim(note == std::string::npos ? value : value.substr(note + 10));
              if (note != std::string::npos)
                value = value.substr(0, note);
              result[key] = trim(value);
            }
        }
      return result;
    }

    /** The words of a value, split at blanks and the separators , ; : of
     * lists and maps. */
    std::vector<std::string>
    words(const std::string &value)
    {
      std::vector<std::string> result(1);
      for (const char c : value)
        if (c == ' ' || c == '\t' || c == ',' || c == ';' || c == ':')
          {
            if (!result.back().empty())
              result.emplace_back();
            if (c != ' ' && c != '\t')
              result.back() = std::string(1, c), result.emplace_back();
          }
        else
          result.back() += c;
      if (result.back().empty())
        result.pop_back();
      return result;
    }

    /** Whether two values say the same: word by word, numbers by value
     * ("1.2" and "1.20", "0.1" and "1e-1"), the rest as text. */
    bool
    same_value(const std::string &a, const std::string &b)
    {
      const auto x = words(a), y = words(b);
      if (x.size() != y.size())
        return false;
      for (unsigned int i = 0; i < x.size(); ++i)
        {
          char        *end_x = nullptr, *end_y = nullptr;
          const double u = std::strtod(x[i].c_str(), &end_x);
          const double v = std::strtod(y[i].c_str(), &end_y);
          const bool   numbers = *end_x == '\0' && *end_y == '\0' &&
                               end_x != x[i].c_str() && end_y != y[i].c_str();
          if (numbers ? u != v : x[i] != y[i])
            return false;
        }
      return true;
    }

    bool
    may_differ(const std::string &key, const std::set<std::string> &may_change)
    {
      if (may_change.count(key) != 0)
        return true;
      const auto slash = key.rfind('/');
      return slash != std::string::npos &&
             may_change.count(key.substr(0, slash) + "/*") != 0;
    }
  } // namespace



  std::vector<std::string>
  parameter_differences(const std::string              &written_file,
                        const dealii::ParameterHandler &now,
                        const std::set<std::string>    &may_change)
  {
    std::ifstream file(written_file);
    const auto    then = entries(file);
    std::stringstream printed;
    now.print_parameters(printed, dealii::ParameterHandler::PRM);
    std::map<std::string, std::string> defaults;
    const auto                         current = entries(printed, &defaults);

    std::vector<std::string> differences;
    const auto               say = [](const auto &map, const std::string &key) {
      const auto it = map.find(key);
      return it == map.end() ? std::string("(absent)") : "\"" + it->second + "\"";
    };
    std::set<std::string> keys;
    for (const auto &[key, value] : then)
      keys.insert(key);
    for (const auto &[key, value] : current)
      keys.insert(key);
    for (const auto &key : keys)
      {
        if (may_differ(key, may_change))
          continue;
        // An entry the run's program did not have yet acted with its
        // default then, as the older program behaved.
        if (then.count(key) == 0)
          {
            if (!same_value(defaults.at(key), current.at(key)))
              differences.push_back(key + ": (absent: its default \"" + defaults.at(key) +
                                    "\") then, " + say(current, key) + " now");
          }
        else if (current.count(key) == 0 || !same_value(then.at(key), current.at(key)))
          differences.push_back(key + ": " + say(then, key) + " then, " +
                                say(current, key) + " now");
      }
    return differences;
  }
} // namespace softopt
