#include "pbrt_tokenizer.h"

#include <charconv>
#include <cmath>

#include "lamina/core/error.h"

namespace lamina::render::pbrt {

namespace {

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f';
}

bool isDelimiter(char c) {
    return isSpace(c) || c == '[' || c == ']' || c == '"' || c == '#';
}

std::string describeByte(char c) {
    static const char* const kHex = "0123456789abcdef";
    const auto u = static_cast<unsigned char>(c);
    return std::string("byte 0x") + kHex[u >> 4] + kHex[u & 15];
}

}  // namespace

Tokenizer::Tokenizer(std::string text, std::string fileName)
    : text_(std::move(text)), fileName_(std::move(fileName)) {}

void Tokenizer::fail(int line, const std::string& message) const {
    throw InputError(fileName_ + ":" + std::to_string(line) + ": " + message);
}

const std::optional<Token>& Tokenizer::peek() {
    if (!hasPeeked_) {
        peeked_ = scan();
        hasPeeked_ = true;
    }
    return peeked_;
}

std::optional<Token> Tokenizer::next() {
    if (hasPeeked_) {
        hasPeeked_ = false;
        return std::move(peeked_);
    }
    return scan();
}

void Tokenizer::skipSpaceAndComments() {
    while (pos_ < text_.size()) {
        const char c = text_[pos_];
        if (c == '\n') {
            ++line_;
            ++pos_;
        } else if (isSpace(c)) {
            ++pos_;
        } else if (c == '#') {
            while (pos_ < text_.size() && text_[pos_] != '\n')
                ++pos_;
        } else {
            return;
        }
    }
}

std::optional<Token> Tokenizer::scan() {
    skipSpaceAndComments();
    if (pos_ >= text_.size()) return std::nullopt;
    const char c = text_[pos_];
    if (c == '[' || c == ']') {
        ++pos_;
        Token t;
        t.kind = c == '[' ? Token::Kind::OpenBracket : Token::Kind::CloseBracket;
        t.text = std::string(1, c);
        t.line = line_;
        return t;
    }
    if (c == '"') return scanString();
    return scanNumberOrWord();
}

Token Tokenizer::scanString() {
    Token t;
    t.kind = Token::Kind::String;
    t.line = line_;
    ++pos_;  // the opening quote
    while (true) {
        if (pos_ >= text_.size()) fail(t.line, "a string is not closed (missing '\"')");
        const char c = text_[pos_++];
        if (c == '"') return t;
        // pbrt-v4's tokenizer refuses a new line inside a string (parser.cpp, Tokenizer::Next).
        if (c == '\n') fail(t.line, "a string is not closed before the end of the line");
        if (c == '\\') {
            if (pos_ >= text_.size()) fail(t.line, "a string is not closed (missing '\"')");
            const char e = text_[pos_++];
            switch (e) {
                case 'b':
                    t.text += '\b';
                    break;
                case 'f':
                    t.text += '\f';
                    break;
                case 'n':
                    t.text += '\n';
                    break;
                case 'r':
                    t.text += '\r';
                    break;
                case 't':
                    t.text += '\t';
                    break;
                case '\\':
                    t.text += '\\';
                    break;
                case '\'':
                    t.text += '\'';
                    break;
                case '"':
                    t.text += '"';
                    break;
                default:
                    fail(t.line, std::string("unknown escape \\") + e + " in a string");
            }
            continue;
        }
        t.text += c;
    }
}

Token Tokenizer::scanNumberOrWord() {
    Token t;
    t.line = line_;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !isDelimiter(text_[pos_])) {
        const auto u = static_cast<unsigned char>(text_[pos_]);
        // Directives, numbers and bare booleans are printable ASCII; anything else is a
        // binary file or a stray character, refused where it is.
        if (u < 0x21 || u > 0x7e) fail(line_, "unexpected " + describeByte(text_[pos_]));
        ++pos_;
    }
    t.text = text_.substr(start, pos_ - start);
    const char first = t.text[0];
    const bool numeric =
        (first >= '0' && first <= '9') || first == '-' || first == '+' || first == '.';
    if (!numeric) {
        t.kind = Token::Kind::Word;
        return t;
    }
    t.kind = Token::Kind::Number;
    const char* begin = t.text.data() + (first == '+' ? 1 : 0);
    const char* end = t.text.data() + t.text.size();
    const auto [ptr, ec] = std::from_chars(begin, end, t.number);
    if (ec != std::errc() || ptr != end || !std::isfinite(t.number))
        fail(t.line, "\"" + t.text + "\" is not a number");
    return t;
}

}  // namespace lamina::render::pbrt
