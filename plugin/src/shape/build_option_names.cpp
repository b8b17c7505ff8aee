// The names of the search methods and shell kinds (core.h), one table each, read both ways.
#include <revolve/baselines.h>
#include <revolve/core.h>

namespace revolve {
namespace {

struct MethodName {
  Method method;
  const char* name;
};
constexpr MethodName kMethodNames[] = {
    {Method::mibit, "mibit"},
    {Method::linear, "linear"},
    {Method::kajiya, "kajiya"},
};

struct ShellName {
  ShellKind shell;
  const char* name;
};
constexpr ShellName kShellNames[] = {
    {ShellKind::cylinder, "cylinder"},
    {ShellKind::cone, "cone"},
    {ShellKind::hybrid, "hybrid"},
};

}  // namespace

const char* methodName(Method method) noexcept {
  for (const MethodName& m : kMethodNames) {
    if (m.method == method) return m.name;
  }
  return "unknown";
}

std::optional<Method> methodNamed(std::string_view name) noexcept {
  for (const MethodName& m : kMethodNames) {
    if (name == m.name) return m.method;
  }
  return std::nullopt;
}

const char* shellKindName(ShellKind shell) noexcept {
  for (const ShellName& s : kShellNames) {
    if (s.shell == shell) return s.name;
  }
  return "unknown";
}

std::optional<ShellKind> shellKindNamed(std::string_view name) noexcept {
  for (const ShellName& s : kShellNames) {
    if (name == s.name) return s.shell;
  }
  return std::nullopt;
}

}  // namespace revolve
