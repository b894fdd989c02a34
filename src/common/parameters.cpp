#include "molsurf/parameters.hpp"

#include <cmath>

#include "common/message_text.hpp"

namespace molsurf {

using detail::number_text;

namespace {

template <class Enum, std::size_t N>
Enum from_name(std::string_view name, const std::string_view (&names)[N], const char* parameter) {
  for (std::size_t i = 0; i < N; ++i)
    if (name == names[i]) return static_cast<Enum>(i);
  throw ParameterError(parameter, choice_problem(name, names));
}

}  // namespace

ParameterError::ParameterError(std::string parameter, std::string problem)
    : Error(parameter + ": " + problem), parameter_(std::move(parameter)), problem_(std::move(problem)) {}

std::string range_text(const NumberParameter& parameter) {
  return (parameter.low_open ? "(" : "[") + number_text(parameter.low) + ", " + number_text(parameter.high) + "]";
}

std::string range_text(const WholeParameter& parameter) {
  return std::to_string(parameter.low) + ".." + std::to_string(parameter.high);
}

std::string problem(const NumberParameter& parameter, double value) {
  if (!std::isfinite(value))
    return number_text(value) + " is not a finite number; expected one in " + range_text(parameter);
  if (value < parameter.low || (parameter.low_open && value == parameter.low) || value > parameter.high)
    return number_text(value) + " is out of range; expected a number in " + range_text(parameter);
  return {};
}

std::string problem(const WholeParameter& parameter, long long value) {
  if (value < parameter.low || value > parameter.high)
    return std::to_string(value) + " is out of range; expected a whole number in " + range_text(parameter);
  return {};
}

void check(const NumberParameter& parameter, double value) {
  if (std::string text = problem(parameter, value); !text.empty())
    throw ParameterError(parameter.name, std::move(text));
}

void check(const WholeParameter& parameter, long long value) {
  if (std::string text = problem(parameter, value); !text.empty())
    throw ParameterError(parameter.name, std::move(text));
}

std::string choice_problem(std::string_view value, std::span<const std::string_view> names) {
  std::string list;
  for (const std::string_view name : names) {
    if (value == name) return {};
    list += (list.empty() ? "" : ", ") + std::string(name);
  }
  return detail::quoted_text(value, 32) + " is not one of: " + list;
}

// The enums list their values in the order of the name tables above.
static_assert(static_cast<int>(SurfaceKind::sas) == 0 && static_cast<int>(SurfaceKind::ses) == 1 &&
              static_cast<int>(SurfaceKind::vdw) == 2);
static_assert(static_cast<int>(SurfaceMethod::one_pass) == 0 && static_cast<int>(SurfaceMethod::pairwise) == 1);
static_assert(static_cast<int>(BooleanOp::union_) == 0 && static_cast<int>(BooleanOp::intersection) == 1 &&
              static_cast<int>(BooleanOp::difference) == 2);

SurfaceKind surface_kind_from_name(std::string_view name) {
  return from_name<SurfaceKind>(name, kSurfaceKindNames, "surface");
}

SurfaceMethod surface_method_from_name(std::string_view name) {
  return from_name<SurfaceMethod>(name, kSurfaceMethodNames, "method");
}

BooleanOp boolean_op_from_name(std::string_view name) { return from_name<BooleanOp>(name, kBooleanOpNames, "op"); }

double surface_probe(SurfaceKind kind, std::optional<double> given) {
  if (given) check(kProbeParameter, *given);
  if (kind == SurfaceKind::vdw) {
    if (given && *given != 0)
      throw ParameterError("probe", "the van der Waals surface (vdw) is the surface at probe 0; give no probe, or 0");
    return 0;
  }
  const double probe = given.value_or(kDefaultProbe);
  if (kind == SurfaceKind::ses && probe == 0)
    throw ParameterError("probe", "the solvent-excluded surface (ses) needs a probe above 0 (at 0 it is the van der "
                                  "Waals surface: vdw)");
  return probe;
}

void validate(const ComputeSurfaceOptions& options) {
  check(kProbeParameter, options.spheres.probe);
  check(kDensityParameter, options.spheres.density);
  if (options.spheres.frequency != 0) check(kFrequencyParameter, options.spheres.frequency);
  check(kThreadsParameter, options.threads);
  if (options.stern_probe) check(kSternProbeParameter, *options.stern_probe);
  if (options.max_sphere_faces < static_cast<std::uint64_t>(kMaxFacesParameter.low) ||
      options.max_sphere_faces > static_cast<std::uint64_t>(kMaxFacesParameter.high))
    throw ParameterError(kMaxFacesParameter.name, std::to_string(options.max_sphere_faces) +
                                                      " is out of range; expected a whole number in " +
                                                      range_text(kMaxFacesParameter));
  if (options.surface == SurfaceKind::ses) {
    surface_probe(SurfaceKind::ses, options.spheres.probe);
    // The SES is drawn from the one-pass SAS and carved by the exact difference: one way.
    if (options.method != SurfaceMethod::one_pass)
      throw ParameterError("method", "'pairwise' is for the SAS and vdW surfaces; the SES is made one way only");
  }
}

std::string radius_set_problem(std::string_view name) {
  const std::vector<std::string> sets = RadiusTable::builtin_names();
  const std::vector<std::string_view> names(sets.begin(), sets.end());
  return choice_problem(name, names);
}

void validate(const ReadOptions& options) {
  if (std::string text = radius_set_problem(options.radius_set); !text.empty())
    throw ParameterError("radius_set", std::move(text));
}

std::vector<std::string> chain_list(std::string_view text) {
  std::vector<std::string> chains;
  while (!text.empty()) {
    const std::size_t comma = text.find(',');
    const std::string_view chain = text.substr(0, comma);
    if (!chain.empty()) chains.emplace_back(chain);
    text.remove_prefix(comma == std::string_view::npos ? text.size() : comma + 1);
  }
  return chains;
}

std::uint64_t memory_limit_bytes(double gigabytes) {
  check(kMaxMemoryParameter, gigabytes);
  return static_cast<std::uint64_t>(gigabytes * 1e9);
}

}  // namespace molsurf
