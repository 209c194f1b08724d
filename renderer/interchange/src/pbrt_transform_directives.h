// The directives of a pbrt-v4 file that change the current transform (Identity, Translate,
// Scale, Rotate, LookAt, Transform, ConcatTransform, CoordinateSystem, CoordSysTransform,
// ActiveTransform, TransformTimes: motion blur), and the readers of a directive's arguments the
// parser shares.
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

/// pbrt-v4's current transform is two (its TransformSet): the one at TransformTimes' start and
/// the one at its end; ActiveTransform chooses which of them the transform directives change.
/// They differ only for a moving (motion-blurred) entity.
struct CurrentTransform {
    glm::dmat4 start{1.0}, end{1.0};
    bool startActive = true, endActive = true;
    bool moves() const { return start != end; }
};

/// TransformTimes: the times of the start and the end transform (pbrt-v4's default 0 and 1).
struct TransformTimes {
    double start = 0, end = 1;
};

/// Reads `directive`'s arguments and applies it to the current transform `ctm` (and the named
/// coordinate systems, the transform times) if it is one of the transform directives; false
/// (nothing read) if not.
bool readTransformDirective(Tokenizer& tokens, const Token& directive, CurrentTransform& ctm,
                            std::map<std::string, CurrentTransform>& coordinateSystems,
                            TransformTimes& times);

}  // namespace lamina::render::pbrt
