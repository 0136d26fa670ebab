#pragma once
// The one error type of graph compilation: a rule and a message naming the pass and resource.
#include <stdexcept>
#include <string>

namespace rg {

enum class Rule {
    UnknownResource,
    NeverWritten,
    FormatUnsupported,
    UsageNotDeclared,
    ExtentMismatch,
    Cycle,
    UnorderedWriters,
    StencilWithoutStencilFormat,
    DepthWithoutDepthFormat,
    ColorOnDepthFormat,
    ImportWithoutFinalLayout,
    ConflictingUses,
    WrongPassType,
    BadDescription,
    ImportChanged,
};

const char* ruleName(Rule rule);

class GraphError : public std::runtime_error {
  public:
    GraphError(Rule rule, const std::string& message)
        : std::runtime_error(message + " [rule: " + ruleName(rule) + "]"), rule_(rule) {}
    Rule rule() const { return rule_; }

  private:
    Rule rule_;
};

}  // namespace rg
