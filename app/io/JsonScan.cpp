// jsontext::scan: one pass over a scene's raw text for what QJsonDocument cannot say. Qt's
// reader keeps the last of two equal keys without a word, it reads `0x10` or `01` as the
// end of a number followed by garbage ("unterminated object", somewhere after it), and so it
// reads a comment or a single-quoted string; it accepts an invalid escape (\l) and drops it. The
// scan follows the JSON grammar (RFC 8259) closely enough to know where values and keys are; at any
// other syntax error it stops and leaves the message to Qt's parser.

#include "app/io/JsonText.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <cctype>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace phasebox::jsontext {

namespace {

// Qt's limit (QJsonDocument refuses deeper documents with its own message).
constexpr int kMaxDepth = 1024;
// Objects with more keys than this look keys up in a hash map instead of a list.
constexpr std::size_t kLinearKeys = 16;
constexpr qsizetype kTokenChars = 40;

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
// The characters a mistyped number runs on with: letters for 0x1F, signs and points.
bool inNumberToken(char c) {
    return isDigit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '+' || c == '-' ||
           c == '.';
}

// Why token is not a JSON number (-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?), or empty.
QString numberProblem(std::string_view t) {
    std::size_t i = 0;
    const std::size_t n = t.size();
    if (i < n && t[i] == '+') return QStringLiteral("JSON numbers have no leading +");
    if (i < n && t[i] == '-') ++i;
    if (i == n) return QStringLiteral("a sign without digits");
    if (t[i] == '.')
        return QStringLiteral("a digit is needed before the decimal point (0.5, not .5)");
    if (!isDigit(t[i])) return QStringLiteral("not a number JSON allows");
    if (t[i] == '0' && i + 1 < n && (t[i + 1] == 'x' || t[i + 1] == 'X'))
        return QStringLiteral("hexadecimal numbers are not JSON; write it in decimal");
    if (t[i] == '0' && i + 1 < n && isDigit(t[i + 1]))
        return QStringLiteral("leading zeros are not allowed (write 1, not 01)");
    while (i < n && isDigit(t[i])) ++i;
    if (i < n && t[i] == '.') {
        ++i;
        if (i == n || !isDigit(t[i]))
            return QStringLiteral("a digit is needed after the decimal point (1.0, not 1.)");
        while (i < n && isDigit(t[i])) ++i;
    }
    if (i < n && (t[i] == 'e' || t[i] == 'E')) {
        ++i;
        if (i < n && (t[i] == '+' || t[i] == '-')) ++i;
        if (i == n || !isDigit(t[i])) return QStringLiteral("the exponent has no digits");
        while (i < n && isDigit(t[i])) ++i;
    }
    if (i != n) return QStringLiteral("not a number JSON allows");
    return {};
}

// A key as compared: the raw bytes between the quotes, or its decoded form when it holds an
// escape (so that "a" and "\u0061" are the same key, as they are to Qt).
struct Key {
    std::string_view text;
    qsizetype offset = 0;
};

struct Frame {
    bool object = false;
    qsizetype index = 0;  // arrays: the element being read
    Key current;          // objects: the key being read
    std::vector<Key> keys;
    std::unordered_map<std::string_view, qsizetype> manyKeys;
    std::vector<std::unique_ptr<std::string>> decoded;  // storage of decoded keys

    void reset(bool isObject) {
        object = isObject;
        index = 0;
        current = {};
        keys.clear();
        manyKeys.clear();
        decoded.clear();
    }
    // The offset of an earlier equal key, or -1; records the key either way.
    qsizetype add(const Key& key) {
        if (!manyKeys.empty() || keys.size() >= kLinearKeys) {
            if (manyKeys.empty())
                for (const Key& k : keys) manyKeys.emplace(k.text, k.offset);
            const auto [it, fresh] = manyKeys.emplace(key.text, key.offset);
            return fresh ? -1 : it->second;
        }
        for (const Key& k : keys)
            if (k.text == key.text) return k.offset;
        keys.push_back(key);
        return -1;
    }
};

class Scanner {
public:
    explicit Scanner(const QByteArray& text) : s_(text.constData()), n_(text.size()) {}

    // Anything after the top-level value is Qt's to report.
    ScanResult run() {
        skipSpace();
        if (value(0) == Stop::Done) skipSpace();  // a comment after the value
        return std::move(result_);
    }

private:
    enum class Stop { Done, Quit };

    // Skips white space; a comment there (JSON has none) is reported and ends the scan.
    void skipSpace() {
        while (p_ < n_ && isSpace(s_[p_])) ++p_;
        if (p_ + 1 < n_ && s_[p_] == '/' && (s_[p_ + 1] == '/' || s_[p_ + 1] == '*')) {
            report(p_,
                   QStringLiteral("JSON has no comments; remove the %1 comment")
                       .arg(s_[p_ + 1] == '/' ? QStringLiteral("//") : QStringLiteral("/* */")));
            p_ = n_;  // every caller quits at the end of the text
        }
    }

    void report(qsizetype offset, const QString& what) {
        if (!result_.problem) result_.problem = SyntaxProblem{offset, what};
    }

    // A string in single quotes, where a value or a key should be.
    Stop singleQuoted() {
        report(p_, QStringLiteral("strings take double quotes (\"...\"), not single quotes"));
        return Stop::Quit;
    }

    Stop value(int depth) {
        if (p_ >= n_) return Stop::Quit;
        const char c = s_[p_];
        if (c == '{' || c == '[') return container(depth, c == '{');
        if (c == '"') {
            std::string_view ignored;
            return string(ignored, nullptr) ? Stop::Done : Stop::Quit;
        }
        if (c == '\'') return singleQuoted();
        if (c == '-' || c == '+' || c == '.' || isDigit(c)) return number();
        for (std::string_view word :
             {std::string_view("true"), std::string_view("false"), std::string_view("null")}) {
            if (std::string_view(s_ + p_, static_cast<std::size_t>(std::min<qsizetype>(
                                              n_ - p_, static_cast<qsizetype>(word.size())))) ==
                word) {
                p_ += static_cast<qsizetype>(word.size());
                return Stop::Done;
            }
        }
        return Stop::Quit;
    }

    Stop number() {
        const qsizetype start = p_;
        while (p_ < n_ && inNumberToken(s_[p_])) ++p_;
        const std::string_view token(s_ + start, static_cast<std::size_t>(p_ - start));
        // NaN and Infinity have their own message in JsonText.cpp.
        std::string word(token.substr(token.empty() || token[0] != '-' ? 0 : 1));
        std::transform(word.begin(), word.end(), word.begin(),
                       [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
        if (word == "nan" || word == "inf" || word == "infinity") return Stop::Quit;
        const QString problem = numberProblem(token);
        if (problem.isEmpty()) return Stop::Done;
        result_.problem =
            SyntaxProblem{start, QStringLiteral("invalid number \"%1\": %2")
                                     .arg(shortened(QString::fromLatin1(
                                              token.data(), static_cast<qsizetype>(token.size()))),
                                          problem)};
        return Stop::Quit;
    }

    // A string at p_ (on its opening quote). raw gets the bytes between the quotes; decoded
    // (when given) the decoded text if there was an escape. False at a malformed string.
    bool string(std::string_view& raw, std::unique_ptr<std::string>* decoded) {
        const qsizetype start = ++p_;
        bool escaped = false;
        while (p_ < n_) {
            const char c = s_[p_];
            if (c == '"') break;
            if (static_cast<unsigned char>(c) < 0x20) return false;
            if (c == '\\') {
                escaped = true;
                if (++p_ >= n_) return false;
                const char e = s_[p_];
                if (e == 'u') {
                    for (int k = 1; k <= 4; ++k)
                        if (p_ + k >= n_ ||
                            !std::isxdigit(static_cast<unsigned char>(s_[p_ + k]))) {
                            report(p_ - 1, QStringLiteral("invalid escape \\u: it takes four "
                                                          "hexadecimal digits (\\u00e9)"));
                            return false;
                        }
                    p_ += 4;
                } else if (std::string_view("\"\\/bfnrt").find(e) == std::string_view::npos) {
                    // Qt drops the backslash: "C:\lessons" would load as "C:lessons".
                    // The whole character, for one outside ASCII (the text is valid UTF-8).
                    QString shown = QString::fromUtf8(s_ + p_, std::min<qsizetype>(4, n_ - p_));
                    shown.truncate(shown.isEmpty() || !shown[0].isHighSurrogate() ? 1 : 2);
                    report(p_ - 1, QStringLiteral("invalid escape \\%1; write \\\\ for a "
                                                  "backslash")
                                       .arg(shown));
                    return false;
                }
            }
            ++p_;
        }
        if (p_ >= n_) return false;
        raw = std::string_view(s_ + start, static_cast<std::size_t>(p_ - start));
        ++p_;  // the closing quote
        if (escaped && decoded) {
            // Qt's own decoding, so that keys compare as QJsonDocument sees them.
            const QByteArray json =
                '"' + QByteArray(raw.data(), static_cast<qsizetype>(raw.size())) + '"';
            const QJsonDocument d = QJsonDocument::fromJson('[' + json + ']');
            *decoded = std::make_unique<std::string>(
                d.isArray() ? d.array().at(0).toString().toStdString() : std::string(raw));
            raw = **decoded;
        }
        return true;
    }

    Stop container(int depth, bool object) {
        if (depth >= kMaxDepth) return Stop::Quit;
        if (static_cast<std::size_t>(depth) >= stack_.size()) stack_.emplace_back();
        stack_[depth].reset(object);
        ++p_;
        skipSpace();
        const char close = object ? '}' : ']';
        if (p_ < n_ && s_[p_] == close) {
            ++p_;
            return Stop::Done;
        }
        while (true) {
            Frame& frame = stack_[depth];
            if (object) {
                if (p_ < n_ && s_[p_] == '\'') return singleQuoted();
                if (p_ >= n_ || s_[p_] != '"') return Stop::Quit;
                const qsizetype keyOffset = p_;
                std::string_view key;
                std::unique_ptr<std::string> decoded;
                if (!string(key, &decoded)) return Stop::Quit;
                if (decoded) frame.decoded.push_back(std::move(decoded));
                frame.current = {key, keyOffset};
                if (const qsizetype earlier = frame.add(frame.current); earlier >= 0)
                    duplicate(depth, earlier, keyOffset);
                skipSpace();
                if (p_ >= n_ || s_[p_] != ':') return Stop::Quit;
                ++p_;
                skipSpace();
            }
            if (value(depth + 1) == Stop::Quit) return Stop::Quit;
            skipSpace();
            if (p_ >= n_) return Stop::Quit;
            if (s_[p_] == close) {
                ++p_;
                return Stop::Done;
            }
            if (s_[p_] != ',') return Stop::Quit;
            ++p_;
            skipSpace();
            ++stack_[depth].index;
        }
    }

    void duplicate(int depth, qsizetype first, qsizetype second) {
        ++result_.duplicateCount;
        if (result_.duplicates.size() >= static_cast<std::size_t>(kMaxReportedDuplicates)) return;
        QString path;
        for (int d = 0; d <= depth; ++d) {
            const Frame& f = stack_[d];
            if (f.object) {
                const QString key = shortened(QString::fromUtf8(
                    f.current.text.data(), static_cast<qsizetype>(f.current.text.size())));
                path += (path.isEmpty() ? QString() : QStringLiteral(".")) + key;
            } else {
                path += QLatin1Char('[') + QString::number(f.index) + QLatin1Char(']');
            }
        }
        result_.duplicates.push_back({path, first, second});
    }

    const char* s_;
    qsizetype n_;
    qsizetype p_ = 0;
    std::vector<Frame> stack_;
    ScanResult result_;
};

}  // namespace

ScanResult scan(const QByteArray& text) {
    return Scanner(text).run();
}

QString shortened(const QString& token) {
    if (token.size() <= kTokenChars + 10) return token;
    qsizetype cut = kTokenChars;
    if (token[cut - 1].isHighSurrogate()) --cut;  // never half a character
    return token.left(cut) + QStringLiteral("... (%1 characters)").arg(token.size());
}

}  // namespace phasebox::jsontext
