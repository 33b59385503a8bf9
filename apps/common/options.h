/*
 * pcl_flowseg apps - one command-line parser for every app: declared options, generated help.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace flowseg_app {

/** \brief Exit statuses of every app. */
constexpr int kExitSuccess = 0;
constexpr int kExitFailure = 1; ///< unreadable input, failed segmentation, unwritable output
constexpr int kExitUsage = 2;   ///< bad options
/** \brief What OptionParser::parse returns when the app should go on. */
constexpr int kContinue = -1;

/** \brief Declares an app's options and parses its arguments. Values are written into the
  * caller's variables, whose values at declaration time are shown in the help as defaults (so
  * defaults come from where the variables were initialised: the library's parameter types).
  * Accepted forms: `-j 2`, `-j2`, `--threads 2`, `--threads=2`. */
class OptionParser
{
public:
  /** \a synopsis: the usage lines (after "Usage: "); \a about: what the app does. */
  OptionParser (std::string app, std::string synopsis, std::string about);

  /** \a names: "-r, --rho" or "--tolerance"; \a value: the value's name in the help ("R"). */
  void flag (const std::string& names, const std::string& help, bool& target);
  void action (const std::string& names, const std::string& help, std::function<void ()> act);
  /** A finite number; \a check (optional) refuses values with the library's message. */
  void number (const std::string& names, const std::string& value, const std::string& help, double& target,
               std::function<pcl_flowseg::Status (double)> check = {});
  /** A whole number in [\a min, \a max]; \a check (optional) refuses values with the library's
    * message. */
  template <class Integer>
  void count (const std::string& names, const std::string& value, const std::string& help, Integer& target,
              long long min, long long max, std::function<pcl_flowseg::Status (long long)> check = {});
  void text (const std::string& names, const std::string& value, const std::string& help, std::string& target);
  /** Three finite numbers X,Y,Z. */
  void point (const std::string& names, const std::string& help, std::optional<Eigen::Vector3d>& target);
  /** One of the named \a choices. */
  template <class T>
  void choice (const std::string& names, const std::string& value, const std::string& help, T& target,
               const std::vector<std::pair<std::string, T>>& choices);
  /** An option whose value \a set interprets: it receives the name used and the value ("" for a
    * switch, whose \a value is "") and returns why it is refused, or "". \a hidden options are
    * accepted but not listed (old spellings). */
  void custom (const std::string& names, const std::string& value, const std::string& help, const std::string& default_text,
               std::function<std::string (const std::string& name, const std::string& value)> set, bool hidden = false);
  /** Another name for the option called \a name, accepted but not listed. */
  void alias (const std::string& alias, const std::string& name);
  /** Text after the options in the help (outputs, exit status). */
  void epilogue (std::string text) { epilogue_ = std::move (text); }

  /** Parses \a argv; arguments that are not options go to \a positionals.
    * \return kContinue, or the status the app should exit with: 0 after --help, kExitUsage after
    *         a usage error (reported on stderr). */
  int parse (int argc, char** argv, std::vector<std::string>& positionals) const;

  /** Reports a usage error on stderr; returns kExitUsage. */
  int usageError (const std::string& message) const;
  /** Reports a failure on stderr; returns kExitFailure. */
  int failure (const std::string& message) const;
  std::string help () const;
  const std::string& app () const { return app_; }

private:
  struct Option
  {
    std::vector<std::string> names;
    std::string value;        ///< empty for switches
    std::string help;
    std::string default_text; ///< empty: none shown
    /** Takes the name used and the value; returns why the value is refused, or "". */
    std::function<std::string (const std::string&, const std::string&)> set;
    bool hidden = false; ///< accepted, not listed in the help
  };
  void add (const std::string& names, const std::string& value, const std::string& help, std::string default_text,
            std::function<std::string (const std::string&)> set);
  const Option* find (const std::string& name) const;
  int apply (const Option& option, const std::string& name, const std::string* value, int argc, char** argv, int& i) const;

  std::string app_, synopsis_, about_, epilogue_;
  std::vector<Option> options_;
  std::vector<std::pair<std::string, std::string>> aliases_;
};

/** \brief The largest whole number an option takes before the library's own check. */
constexpr long long kLargestCount = 1000000000000LL;

/** \brief Parses a whole number; false when \a text is not exactly one in [min, max]. */
bool
parseWhole (const std::string& text, long long min, long long max, long long& value);

/** \brief Text of a default value as the help shows it. */
std::string
defaultText (double value);

template <class Integer>
void
OptionParser::count (const std::string& names, const std::string& value, const std::string& help, Integer& target,
                     long long min, long long max, std::function<pcl_flowseg::Status (long long)> check)
{
  Integer* t = &target;
  const std::string first = names.substr (names.rfind (' ') + 1);
  add (names, value, help, std::to_string (target), [t, min, max, first, check] (const std::string& text) {
    long long v = 0;
    if (!parseWhole (text, min, max, v))
      return first + " needs a whole number from " + std::to_string (min) + " to " + std::to_string (max) + ", got '" + text + "'";
    if (check)
      if (const pcl_flowseg::Status s = check (v); !s)
        return first + ": " + s.message;
    *t = static_cast<Integer> (v);
    return std::string ();
  });
}

template <class T>
void
OptionParser::choice (const std::string& names, const std::string& value, const std::string& help, T& target,
                      const std::vector<std::pair<std::string, T>>& choices)
{
  std::string list, current;
  for (std::size_t k = 0; k < choices.size (); ++k)
  {
    list += (k == 0 ? "" : k + 1 == choices.size () ? " or " : ", ") + choices[k].first;
    if (choices[k].second == target)
      current = choices[k].first;
  }
  T* t = &target;
  const std::string first = names.substr (names.rfind (' ') + 1);
  add (names, value, help, current, [t, choices, list, first] (const std::string& text) {
    for (const auto& c : choices)
      if (c.first == text)
      {
        *t = c.second;
        return std::string ();
      }
    return first + " must be " + list + ", got '" + text + "'";
  });
}

} // namespace flowseg_app
