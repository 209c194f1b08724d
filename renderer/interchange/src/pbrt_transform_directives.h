// The directives of a pbrt-v4 file that change the current transform (Identity, Translate,
// Scale, Rotate, LookAt, Transform, ConcatTransform, CoordinateSystem, CoordSysTransform,
// ActiveTransform, TransformTimes), and the readers of a directive's arguments the parser shares.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "pbrt_tokenizer.h"

namespace lamina::render::pbrt {

/// The next token, which must be of `kind` (`what` names it in the message; `line` is the
/// directive's, for the end of the file).
Token expectToken(Tokenizer& tokens, Token::Kind kind, const std::string& what, int line);
/// The quoted string after `directive`.
std::string quotedString(Tokenizer& tokens, const Token& directive);
/// `count` numbers after `directive`, in brackets or not where `bracketsAllowed`.
std::vector<double> directiveNumbers(Tokenizer& tokens, const Token& directive, std::size_t count,
                                     bool bracketsAllowed);

/// Reads `directive`'s arguments and applies it to the current transform `ctm` (and the named
/// coordinate systems) if it is one of the transform directives; false (nothing read) if not.
/// What lamina ignores is said in `warnings`, as "FILE:LINE: message".
bool readTransformDirective(Tokenizer& tokens, const Token& directive, glm::dmat4& ctm,
                            std::map<std::string, glm::dmat4>& coordinateSystems,
                            std::vector<std::string>& warnings);

}  // namespace lamina::render::pbrt
