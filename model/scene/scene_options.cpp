// Names of the shading options, as scene files and the command line spell them.
#include "scene.hpp"

namespace watkins {

const char* to_string(ShadingRule r) {
  switch (r) {
    case ShadingRule::Gouraud: return "gouraud";
    case ShadingRule::Lambert: return "lambert";
    case ShadingRule::Warnock: return "warnock";
    case ShadingRule::Romney: return "romney";
    case ShadingRule::Phong: return "phong";
  }
  return "?";
}

const char* to_string(DepthMode m) { return m == DepthMode::InverseZ ? "inverse-z" : "z"; }

const char* to_string(Interpolation i) { return i == Interpolation::Eq1 ? "eq1" : "eq2"; }

std::optional<Interpolation> parse_interpolation(const std::string& s) {
  for (Interpolation i : {Interpolation::Eq1, Interpolation::Eq2})
    if (s == to_string(i)) return i;
  return std::nullopt;
}

const char* to_string(DepthTie t) { return t == DepthTie::Arrival ? "arrival" : "submission"; }

std::optional<DepthTie> parse_depth_tie(const std::string& s) {
  for (DepthTie t : {DepthTie::Arrival, DepthTie::Submission})
    if (s == to_string(t)) return t;
  return std::nullopt;
}

std::optional<ShadingRule> parse_shading_rule(const std::string& s) {
  for (ShadingRule r : {ShadingRule::Gouraud, ShadingRule::Lambert, ShadingRule::Warnock, ShadingRule::Romney,
                        ShadingRule::Phong})
    if (s == to_string(r)) return r;
  return std::nullopt;
}

std::optional<DepthMode> parse_depth_mode(const std::string& s) {
  for (DepthMode m : {DepthMode::InverseZ, DepthMode::Z})
    if (s == to_string(m)) return m;
  return std::nullopt;
}

const char* to_string(ShadingMode m) { return m == ShadingMode::Gouraud ? "gouraud" : "phong"; }

std::optional<ShadingMode> parse_shading_mode(const std::string& s) {
  for (ShadingMode m : {ShadingMode::Gouraud, ShadingMode::Phong})
    if (s == to_string(m)) return m;
  return std::nullopt;
}

}  // namespace watkins
