#include "document/jsonlocate.h"

namespace sylva::doc {

namespace {

class Walker {
public:
    explicit Walker(const std::string& text) : mText(text) {}

    std::size_t pos = 0;

    void space() {
        while (pos < mText.size() && (mText[pos] == ' ' || mText[pos] == '\t' ||
                                      mText[pos] == '\n' || mText[pos] == '\r'))
            ++pos;
    }
    bool at(char c) {
        space();
        return pos < mText.size() && mText[pos] == c;
    }
    /// A string at pos (its opening quote); returns its raw content, pos after it.
    std::string string() {
        std::string out;
        ++pos;
        while (pos < mText.size() && mText[pos] != '"') {
            if (mText[pos] == '\\' && pos + 1 < mText.size()) out += mText[pos++];
            out += mText[pos++];
        }
        ++pos;
        return out;
    }
    /// Skips the value at pos.
    void skip() {
        space();
        if (pos >= mText.size()) return;
        const char c = mText[pos];
        if (c == '"') {
            string();
        } else if (c == '{' || c == '[') {
            int depth = 0;
            while (pos < mText.size()) {
                const char d = mText[pos];
                if (d == '"') {
                    string();
                    continue;
                }
                if (d == '{' || d == '[') ++depth;
                if (d == '}' || d == ']') --depth;
                ++pos;
                if (depth == 0) return;
            }
        } else {
            while (pos < mText.size() && mText[pos] != ',' && mText[pos] != '}' &&
                   mText[pos] != ']' && mText[pos] != ' ' && mText[pos] != '\n' &&
                   mText[pos] != '\r' && mText[pos] != '\t')
                ++pos;
        }
    }
    /// Moves to the member \p key of the object at pos (to its key when \p toKey); false when
    /// it has none.
    bool member(const std::string& key, bool toKey) {
        if (!at('{')) return false;
        ++pos;
        while (true) {
            if (!at('"')) return false;
            const std::size_t keyPos = pos;
            const std::string k = string();
            if (!at(':')) return false;
            ++pos;
            space();
            if (k == key) {
                if (toKey) pos = keyPos;
                return true;
            }
            skip();
            if (!at(',')) return false;
            ++pos;
        }
    }
    bool element(std::size_t index) {
        if (!at('[')) return false;
        ++pos;
        for (std::size_t i = 0;; ++i) {
            space();
            if (i == index) return pos < mText.size() && mText[pos] != ']';
            skip();
            if (!at(',')) return false;
            ++pos;
        }
    }

private:
    const std::string& mText;
};

} // namespace

JsonPlace locateJson(const std::string& text, const std::vector<JsonStep>& path) {
    Walker w(text);
    w.space();
    std::size_t found = w.pos;
    for (std::size_t s = 0; s < path.size(); ++s) {
        const bool last = s + 1 == path.size();
        const std::size_t before = w.pos;
        const bool ok = std::holds_alternative<std::string>(path[s])
                            ? w.member(std::get<std::string>(path[s]), last)
                            : w.element(std::get<std::size_t>(path[s]));
        if (!ok) {
            w.pos = before;
            break;
        }
        found = w.pos;
    }
    JsonPlace place;
    for (std::size_t i = 0; i < found && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++place.line;
            place.column = 1;
        } else {
            ++place.column;
        }
    }
    return place;
}

} // namespace sylva::doc
