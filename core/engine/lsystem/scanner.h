#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "engine/util/error.h"

namespace sylva::lsys {

/// Internal: a cursor over one line of grammar text that knows its file position, shared by
/// the grammar parser and the expression compiler so every diagnostic carries line and column.
class Scanner {
public:
    Scanner(std::string_view line, int lineNumber, const std::string& fileName,
            std::vector<Diagnostic>& diagnostics)
        : mText(line), mLine(lineNumber), mFile(fileName), mDiagnostics(diagnostics) {}

    void skipSpaces() {
        while (mPos < mText.size() &&
               (mText[mPos] == ' ' || mText[mPos] == '\t' || mText[mPos] == '\r'))
            ++mPos;
    }
    /// True at the end of the line or at a comment.
    bool atEnd() {
        skipSpaces();
        return mPos >= mText.size() || mText[mPos] == '#';
    }
    char peek(std::size_t ahead = 0) const {
        return mPos + ahead < mText.size() ? mText[mPos + ahead] : '\0';
    }
    void advance(std::size_t n = 1) { mPos += n; }
    bool atArrow() {
        skipSpaces();
        return peek() == '-' && peek(1) == '>';
    }
    bool consume(char c) {
        skipSpaces();
        if (peek() != c) return false;
        ++mPos;
        return true;
    }
    std::size_t position() const { return mPos; }
    void setPosition(std::size_t p) { mPos = p; }
    /// 1-based column of the current position (or of \p pos).
    int column() const { return static_cast<int>(mPos) + 1; }
    int columnAt(std::size_t pos) const { return static_cast<int>(pos) + 1; }
    int line() const { return mLine; }
    std::string_view text() const { return mText; }
    const std::string& fileName() const { return mFile; }

    void error(int column, std::string message) {
        mDiagnostics.push_back({mFile, mLine, column, std::move(message)});
    }
    void error(std::string message) { error(column(), std::move(message)); }
    std::size_t errorCount() const { return mDiagnostics.size(); }

    /// Describes the character at the cursor for messages ("end of line", "'x'").
    std::string describeHere() {
        if (atEnd()) return "end of line";
        return std::string("'") + peek() + "'";
    }

private:
    std::string_view mText;
    std::size_t mPos = 0;
    int mLine;
    const std::string& mFile;
    std::vector<Diagnostic>& mDiagnostics;
};

} // namespace sylva::lsys
