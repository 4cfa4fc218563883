// C-like expressions of cpfg: arithmetic, comparison, logic, `?:`, `^` as power, calls of the built-in
// functions, array elements and variables resolved through a scope.
#pragma once

#include <optional>
#include <string>

#include "ir/expr.h"
#include "lang/text_cursor.h"

namespace simeco::lang {

// Resolves names while an expression is parsed.
class ExprScope {
public:
    virtual ~ExprScope() = default;
    // A variable as a Local or Global expression, or nothing when the name is unknown.
    virtual std::optional<ir::Expr> variable(const std::string& name) const = 0;
    // The slot of a global array, or nothing.
    virtual std::optional<int> array(const std::string& name) const = 0;
};

// Where an expression may cross a line break outside parentheses (inside them it always may).
enum class NewlinePolicy {
    Always,          // statement blocks `{ ... }`
    TabContinuation, // production lines: only onto a line that starts with a tab, as cpfg reads them
};

struct ExprOptions {
    NewlinePolicy newlines = NewlinePolicy::Always;
};

// Parses one expression at the cursor. Stops before anything that cannot continue it (`,` `)` `-->` `{` ...).
ir::Expr parseExpression(TextCursor& cur, const ExprScope& scope, ExprOptions options = {});

// Parses a C floating literal at the cursor (digits, optional fraction and exponent), in double precision.
std::optional<double> parseNumber(TextCursor& cur);

} // namespace simeco::lang
