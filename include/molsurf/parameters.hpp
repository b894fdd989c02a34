#pragma once
// The parameters a user gives a job (probe, density, threads, the surface kind, the Boolean
// operation, ...): their ranges, their names and the rules between them, decided here once
// for every front end. The command line and Python only translate arguments and ask here,
// so both accept the same values and refuse the others with the same words.
//
// A refusal is a ParameterError: the parameter's name as the library and Python spell it
// ("probe", "max_faces") and the problem ("-1 is out of range; expected a number in
// [0, 1e+15]"). what() is "NAME: PROBLEM"; the command line puts its own spelling of the
// option in front of the problem instead ("--probe: ...").
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/error.hpp"
#include "molsurf/surface.hpp"

namespace molsurf {

class ParameterError : public Error {
 public:
  ParameterError(std::string parameter, std::string problem);
  const std::string& parameter() const { return parameter_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string parameter_, problem_;
};

// A real-valued parameter: finite and in [low, high] (or (low, high] when low_open).
struct NumberParameter {
  const char* name;
  double low, high;
  bool low_open = false;
};

// A whole-numbered parameter in [low, high].
struct WholeParameter {
  const char* name;
  long long low, high;
};

inline constexpr NumberParameter kProbeParameter{"probe", 0, 1e15};               // angstrom
inline constexpr NumberParameter kSternProbeParameter{"stern_probe", 0, 1e15};    // angstrom
inline constexpr NumberParameter kDensityParameter{"density", 0, 1e9, true};      // vertices per A^2
inline constexpr NumberParameter kMaxMemoryParameter{"max_memory", 0, 1e9, true};  // GB
inline constexpr NumberParameter kBoxMarginParameter{"box_margin", 0, 1e6, true};  // angstrom
inline constexpr NumberParameter kVolumeSizeParameter{"volume_size", 0, 1e6, true};
inline constexpr WholeParameter kFrequencyParameter{"frequency", 1, 200};
inline constexpr WholeParameter kThreadsParameter{"threads", 0, 1024};  // 0: all cores
inline constexpr WholeParameter kMaxFacesParameter{"max_faces", 1, 100'000'000'000};
// Spatial blocks (--blocks): a file each with .pvtp; 65 536 blocks of 10^9 atoms hold 15 000 each.
inline constexpr WholeParameter kBlocksParameter{"blocks", 1, 65536};

// "[0, 1e+15]", "(0, 1e+09]", "1..200": the range as messages and --help print it.
std::string range_text(const NumberParameter& parameter);
std::string range_text(const WholeParameter& parameter);
// What is wrong with `value`, or an empty string when it is in range. Numbers print with %g
// ("1e+16", "nan"), never as 309 digits.
std::string problem(const NumberParameter& parameter, double value);
std::string problem(const WholeParameter& parameter, long long value);
// Throw ParameterError unless `value` is in range.
void check(const NumberParameter& parameter, double value);
void check(const WholeParameter& parameter, long long value);

// The names a parameter with a fixed set of values takes are beside its enum
// (kSurfaceKindNames, kSurfaceMethodNames, kBooleanOpNames), in the order messages list them.
// "'xor' is not one of: union, intersection, difference", or empty when `value` is one.
std::string choice_problem(std::string_view value, std::span<const std::string_view> names);

// Each throws ParameterError ("surface", "method", "op", "radius_set") for another name.
SurfaceKind surface_kind_from_name(std::string_view name);
SurfaceMethod surface_method_from_name(std::string_view name);
BooleanOp boolean_op_from_name(std::string_view name);

// The default probe radius (a water molecule), A.
inline constexpr double kDefaultProbe = 1.4;

// The probe radius a surface of `kind` gets from the probe the user gave (nullopt: none):
// the van der Waals surface is the one at probe 0, so a probe other than 0 given with it is
// refused (it would be silently ignored otherwise); the SES rolls a probe, so it needs one
// above 0. Throws ParameterError ("probe").
double surface_probe(SurfaceKind kind, std::optional<double> given);

// Every parameter of a surface job in range, and the rules between them (the SES has one
// method). compute_surface checks the same; front ends ask first, before reading anything.
void validate(const ComputeSurfaceOptions& options);
// "'vdw' is not one of: bondi, naccess, protor" unless `name` is a built-in radius set.
std::string radius_set_problem(std::string_view name);
// The radius set is a built-in one (checked even with a radius_file, which overrides it).
void validate(const ReadOptions& options);

// "A,C" -> {"A", "C"}: a chain list as one text, empty entries skipped ("" keeps every chain).
std::vector<std::string> chain_list(std::string_view text);

// A memory limit given in GB (kMaxMemoryParameter's range), in bytes.
std::uint64_t memory_limit_bytes(double gigabytes);

}  // namespace molsurf
