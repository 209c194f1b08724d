// The lexical layer of pbrt-v4 scene files (pbrt-v4's file-format documentation, "Scene
// description format"): words (directives, bare true/false), numbers, quoted strings with
// pbrt's escapes, `[` and `]`, and `#` comments to the end of the line. Every token carries
// its line for the "FILE:LINE: ..." messages. Bounded: the text is held once, tokens are made
// one at a time, and a byte that no pbrt file contains (a binary file) is refused at once.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace lamina::render::pbrt {

struct Token {
    enum class Kind { Word, String, Number, OpenBracket, CloseBracket };
    Kind kind = Kind::Word;
    std::string text;  ///< the word, the string's contents (unescaped) or the number's spelling
    double number = 0;
    int line = 1;
};

/// Splits one file's text into tokens. Errors are InputErrors "FILE:LINE: what was wrong".
class Tokenizer {
  public:
    Tokenizer(std::string text, std::string fileName);

    /// The next token, or nullopt at the end of the text.
    std::optional<Token> next();
    /// The next token without consuming it.
    const std::optional<Token>& peek();

    const std::string& fileName() const { return fileName_; }
    /// The line the tokenizer is at (the last token's, or where the text ended).
    int line() const { return line_; }
    [[noreturn]] void fail(int line, const std::string& message) const;

  private:
    std::optional<Token> scan();
    void skipSpaceAndComments();
    Token scanString();
    Token scanNumberOrWord();

    std::string text_;
    std::string fileName_;
    std::size_t pos_ = 0;
    int line_ = 1;
    std::optional<Token> peeked_;
    bool hasPeeked_ = false;
};

}  // namespace lamina::render::pbrt
