#include "options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "usage_error.hpp"

namespace watkins::cli {

namespace {

std::string in_quotes(const std::string& s) { return "\"" + s + "\""; }

// Exactly a decimal integer: an optional '-' and digits, nothing before or after.
bool exact_integer(const std::string& s, long long& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return !s.empty() && r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// Exactly a finite real number (strtod's syntax, nothing after it; no "nan", no "inf").
bool exact_finite(const std::string& s, double& v) {
  if (s.empty() || std::isspace(static_cast<unsigned char>(s.front()))) return false;
  try {
    std::size_t used = 0;
    v = std::stod(s, &used);
    return used == s.size() && std::isfinite(v);
  } catch (const std::exception&) {
    return false;  // std::out_of_range (1e999) included: not a finite double
  }
}

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string finite_error(const std::string& s, double lo, double hi) {
  double v = 0;
  if (!exact_finite(s, v)) return "expected a finite number, got " + in_quotes(s);
  if (v < lo || v > hi) return "expected a number in [" + number_text(lo) + ", " + number_text(hi) + "], got " + in_quotes(s);
  return "";
}

std::string integer_error(const std::string& s, long long lo, long long hi) {
  long long v = 0;
  if (!exact_integer(s, v) || v < lo || v > hi)
    return "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + in_quotes(s);
  return "";
}

// Each occurrence's items, split at commas; an empty item is an error naming the option.
std::vector<std::string> items(const std::string& option, const std::vector<std::string>& given) {
  std::vector<std::string> out;
  for (const std::string& g : given) {
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = g.find(',', start);
      std::string item = g.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      if (item.empty()) throw CLI::ValidationError(option, "empty item in " + in_quotes(g));
      out.push_back(std::move(item));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return out;
}

template <class T>
std::string default_list(const std::vector<T>& v) {
  std::string s;
  for (const T& x : v) {
    std::ostringstream o;
    o << x;
    s += (s.empty() ? "" : ",") + o.str();
  }
  return "[" + s + "]";
}

}  // namespace

CLI::Validator finite_in(double lo, double hi) {
  return CLI::Validator([lo, hi](std::string& s) { return finite_error(s, lo, hi); },
                        "FLOAT in [" + number_text(lo) + " - " + number_text(hi) + "]");
}

CLI::Validator integer_in(long long lo, long long hi) {
  return CLI::Validator([lo, hi](std::string& s) { return integer_error(s, lo, hi); },
                        "INT in [" + std::to_string(lo) + " - " + std::to_string(hi) + "]");
}

CLI::Validator seed64() {
  return CLI::Validator(
      [](std::string& s) {
        unsigned long long v = 0;
        const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
        if (!s.empty() && r.ec == std::errc() && r.ptr == s.data() + s.size()) return std::string();
        return "expected an integer in [0, 18446744073709551615], got " + in_quotes(s);
      },
      "SEED");
}

CLI::Validator non_empty_name() {
  return CLI::Validator([](std::string& s) { return s.empty() ? std::string("the name is empty") : std::string(); },
                        "");
}

CLI::Option* add_file(CLI::App* app, const std::string& name, std::string& target, const std::string& help) {
  return app->add_option(name, target, help)->check(non_empty_name());
}

CLI::Option* add_real_list(CLI::App* app, const std::string& name, std::vector<double>& target,
                           const std::string& help, double lo, double hi) {
  const std::string shown = name.substr(name.rfind(',') == std::string::npos ? 0 : name.rfind(',') + 1);
  CLI::Option* o = app->add_option_function<std::vector<std::string>>(
      name,
      [&target, shown, lo, hi](const std::vector<std::string>& given) {
        std::vector<double> values;
        for (const std::string& s : items(shown, given)) {
          if (std::string e = finite_error(s, lo, hi); !e.empty()) throw CLI::ValidationError(shown, e);
          values.push_back(std::stod(s));
        }
        target = values;
      },
      help);
  o->type_name("FLOAT:FLOAT in [" + number_text(lo) + " - " + number_text(hi) + "]");
  if (!target.empty()) o->default_str(default_list(target));
  return o;
}

CLI::Option* add_int_list(CLI::App* app, const std::string& name, std::vector<int>& target, const std::string& help,
                          int lo, int hi) {
  const std::string shown = name.substr(name.rfind(',') == std::string::npos ? 0 : name.rfind(',') + 1);
  CLI::Option* o = app->add_option_function<std::vector<std::string>>(
      name,
      [&target, shown, lo, hi](const std::vector<std::string>& given) {
        std::vector<int> values;
        for (const std::string& s : items(shown, given)) {
          if (std::string e = integer_error(s, lo, hi); !e.empty()) throw CLI::ValidationError(shown, e);
          values.push_back(static_cast<int>(std::stoll(s)));
        }
        target = values;
      },
      help);
  o->type_name("INT:INT in [" + std::to_string(lo) + " - " + std::to_string(hi) + "]");
  if (!target.empty()) o->default_str(default_list(target));
  return o;
}

CLI::Option* add_name_list(CLI::App* app, const std::string& name, std::vector<std::string>& target,
                           const std::string& help, const std::vector<std::string>& allowed) {
  const std::string shown = name.substr(name.rfind(',') == std::string::npos ? 0 : name.rfind(',') + 1);
  std::string set;
  for (const std::string& a : allowed) set += (set.empty() ? "" : ",") + a;
  CLI::Option* o = app->add_option_function<std::vector<std::string>>(
      name,
      [&target, shown, allowed, set](const std::vector<std::string>& given) {
        std::vector<std::string> values = items(shown, given);
        for (const std::string& s : values)
          if (std::find(allowed.begin(), allowed.end(), s) == allowed.end())
            throw CLI::ValidationError(shown, in_quotes(s) + " is not one of " + set);
        target = values;
      },
      help);
  o->type_name("TEXT:{" + set + "}");
  if (!target.empty()) o->default_str(default_list(target));
  return o;
}

CLI::Option* add_shading(CLI::App* app, std::string& target, const std::string& help) {
  return app->add_option("--shading", target, help)
      ->check(CLI::Validator(
          [](std::string& s) {
            return parse_shading_mode(s) ? std::string()
                                         : "unknown shading mode " + in_quotes(s) + " (gouraud, phong)";
          },
          "gouraud|phong"));
}

BuildOptions shading_options(const std::string& name) {
  BuildOptions opt;
  if (!name.empty()) opt.shading = parse_shading_mode(name);
  return opt;
}

void parse_shard(const std::string& option, const std::string& text, long long& i, long long& n) {
  const std::size_t slash = text.find('/');
  const auto digits = [](const std::string& s) {
    return !s.empty() && s.size() <= 18 && s.find_first_not_of("0123456789") == std::string::npos;
  };
  const std::string a = text.substr(0, slash), b = slash == std::string::npos ? "" : text.substr(slash + 1);
  if (slash == std::string::npos || !digits(a) || !digits(b))
    throw UsageError(option + ": expected i/N (two whole numbers, 0 <= i < N), got " + in_quotes(text));
  i = std::stoll(a);
  n = std::stoll(b);
  if (n < 1 || i >= n) throw UsageError(option + ": expected i/N with 0 <= i < N, got " + in_quotes(text));
}

void exclusive(const std::vector<CLI::Option*>& options) {
  for (std::size_t a = 0; a < options.size(); ++a)
    for (std::size_t b = a + 1; b < options.size(); ++b) options[a]->excludes(options[b]);
}

}  // namespace watkins::cli
