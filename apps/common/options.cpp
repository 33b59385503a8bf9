/*
 * pcl_flowseg apps - one command-line parser for every app: declared options, generated help.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/options.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace flowseg_app {

namespace {
constexpr std::size_t kHelpColumn = 25;

std::vector<std::string>
splitNames (const std::string& names)
{
  std::vector<std::string> out;
  std::stringstream in (names);
  for (std::string name; std::getline (in, name, ',');)
  {
    const std::size_t a = name.find_first_not_of (' ');
    out.push_back (name.substr (a, name.find_last_not_of (' ') - a + 1));
  }
  return out;
}

bool
parseFinite (const std::string& text, double& value)
{
  char* end = nullptr;
  errno = 0;
  value = std::strtod (text.c_str (), &end);
  return !text.empty () && *end == '\0' && std::isfinite (value);
}

/** \a text with every line after the first indented to the help column. */
std::string
indented (const std::string& text)
{
  std::string out;
  for (const char c : text)
  {
    out += c;
    if (c == '\n')
      out += std::string (kHelpColumn, ' ');
  }
  return out;
}
/** \a text with lines longer than the help's width broken at spaces (its own line breaks kept). */
std::string
wrapped (const std::string& text)
{
  constexpr std::size_t kWidth = 100 - kHelpColumn;
  std::string out, line;
  std::stringstream in (text);
  for (std::string given; std::getline (in, given);)
  {
    std::stringstream words (given);
    line.clear ();
    for (std::string word; words >> word;)
    {
      if (!line.empty () && line.size () + 1 + word.size () > kWidth)
      {
        out += line + "\n";
        line.clear ();
      }
      line += (line.empty () ? "" : " ") + word;
    }
    out += line + "\n";
  }
  if (!out.empty ())
    out.pop_back ();
  return out;
}
} // namespace

bool
parseWhole (const std::string& text, long long min, long long max, long long& value)
{
  char* end = nullptr;
  errno = 0;
  value = std::strtoll (text.c_str (), &end, 10);
  return !text.empty () && *end == '\0' && errno == 0 && value >= min && value <= max;
}

std::string
defaultText (double value)
{
  std::ostringstream s;
  s << value;
  return s.str ();
}

OptionParser::OptionParser (std::string app, std::string synopsis, std::string about)
  : app_ (std::move (app)), synopsis_ (std::move (synopsis)), about_ (std::move (about))
{
}

void
OptionParser::add (const std::string& names, const std::string& value, const std::string& help, std::string default_text,
                   std::function<std::string (const std::string&)> set)
{
  options_.push_back (Option{splitNames (names), value, help, std::move (default_text),
                             [set] (const std::string&, const std::string& text) { return set (text); }});
}

void
OptionParser::custom (const std::string& names, const std::string& value, const std::string& help,
                      const std::string& default_text, std::function<std::string (const std::string&, const std::string&)> set,
                      bool hidden)
{
  options_.push_back (Option{splitNames (names), value, help, default_text, std::move (set), hidden});
}

void
OptionParser::flag (const std::string& names, const std::string& help, bool& target)
{
  bool* t = &target;
  add (names, "", help, "", [t] (const std::string&) {
    *t = true;
    return std::string ();
  });
}

void
OptionParser::action (const std::string& names, const std::string& help, std::function<void ()> act)
{
  add (names, "", help, "", [act] (const std::string&) {
    act ();
    return std::string ();
  });
}

void
OptionParser::number (const std::string& names, const std::string& value, const std::string& help, double& target,
                      std::function<pcl_flowseg::Status (double)> check)
{
  double* t = &target;
  const std::string first = splitNames (names).back ();
  add (names, value, help, defaultText (target), [t, check, first] (const std::string& text) {
    double v = 0.0;
    if (!parseFinite (text, v))
      return first + " needs a finite number, got '" + text + "'";
    if (check)
      if (const pcl_flowseg::Status s = check (v); !s)
        return first + ": " + s.message;
    *t = v;
    return std::string ();
  });
}

void
OptionParser::text (const std::string& names, const std::string& value, const std::string& help, std::string& target)
{
  std::string* t = &target;
  const std::string first = splitNames (names).back ();
  add (names, value, help, target, [t, first] (const std::string& text) {
    if (text.empty ())
      return first + " needs a value";
    *t = text;
    return std::string ();
  });
}

void
OptionParser::point (const std::string& names, const std::string& help, std::optional<Eigen::Vector3d>& target)
{
  std::optional<Eigen::Vector3d>* t = &target;
  const std::string first = splitNames (names).back ();
  add (names, "X,Y,Z", help, "", [t, first] (const std::string& text) {
    double x, y, z;
    char c1 = 0, c2 = 0, extra = 0;
    if (std::sscanf (text.c_str (), "%lf%c%lf%c%lf%c", &x, &c1, &y, &c2, &z, &extra) != 5 || c1 != ',' || c2 != ',' ||
        !std::isfinite (x) || !std::isfinite (y) || !std::isfinite (z))
      return first + " needs X,Y,Z (three finite numbers), got '" + text + "'";
    *t = Eigen::Vector3d (x, y, z);
    return std::string ();
  });
}

void
OptionParser::alias (const std::string& alias, const std::string& name)
{
  aliases_.emplace_back (alias, name);
}

const OptionParser::Option*
OptionParser::find (const std::string& name) const
{
  std::string wanted = name;
  for (const auto& a : aliases_)
    if (a.first == name)
      wanted = a.second;
  for (const Option& o : options_)
    for (const std::string& n : o.names)
      if (n == wanted)
        return &o;
  return nullptr;
}

int
OptionParser::apply (const Option& option, const std::string& name, const std::string* value, int argc, char** argv,
                     int& i) const
{
  std::string given;
  if (option.value.empty ())
  {
    if (value)
      return usageError (name + " takes no value");
  }
  else if (value)
    given = *value;
  else if (i + 1 < argc)
    given = argv[++i];
  else
    return usageError (name + " needs a value (" + option.value + ")");
  const std::string why = option.set (name, given);
  return why.empty () ? kContinue : usageError (why);
}

int
OptionParser::parse (int argc, char** argv, std::vector<std::string>& positionals) const
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help")
    {
      std::cout << help ();
      return kExitSuccess;
    }
    if (arg.size () < 2 || arg[0] != '-')
    {
      positionals.push_back (arg);
      continue;
    }
    std::string name = arg, value;
    bool inline_value = false;
    if (arg.compare (0, 2, "--") == 0 && arg.find ('=') != std::string::npos)
    {
      name = arg.substr (0, arg.find ('='));
      value = arg.substr (arg.find ('=') + 1);
      inline_value = true;
    }
    else if (arg[1] != '-' && arg.size () > 2 && !find (arg))
    {
      name = arg.substr (0, 2); // -j2: a short option with its value attached
      value = arg.substr (2);
      inline_value = true;
    }
    const Option* option = find (name);
    if (!option)
      return usageError ("unknown option '" + arg + "'");
    if (const int status = apply (*option, name, inline_value ? &value : nullptr, argc, argv, i); status != kContinue)
      return status;
  }
  return kContinue;
}

int
OptionParser::usageError (const std::string& message) const
{
  std::cerr << app_ << ": " << message << "\n(see " << app_ << " --help)\n";
  return kExitUsage;
}

int
OptionParser::failure (const std::string& message) const
{
  std::cerr << app_ << ": " << message << "\n";
  return kExitFailure;
}

std::string
OptionParser::help () const
{
  std::string out = "Usage: " + synopsis_ + "\n\n" + about_ + "\n\nOptions:\n";
  for (const Option& o : options_)
  {
    if (o.hidden)
      continue;
    std::string left = "  ";
    if (o.names.front ().compare (0, 2, "--") == 0)
      left += "    ";
    for (std::size_t k = 0; k < o.names.size (); ++k)
      left += (k ? ", " : "") + o.names[k];
    if (!o.value.empty ())
      left += " " + o.value;
    left += left.size () + 1 < kHelpColumn ? std::string (kHelpColumn - left.size (), ' ') : "\n" + std::string (kHelpColumn, ' ');
    out += left + indented (wrapped (o.help + (o.default_text.empty () ? "" : " (default " + o.default_text + ")"))) + "\n";
  }
  out += "  -h, --help             this help\n";
  if (!epilogue_.empty ())
    out += "\n" + epilogue_ + "\n";
  return out;
}

} // namespace flowseg_app
