#include "engine/graph/fileparams.h"

namespace sylva::graph {

bool isFileParam(const std::string& key) {
    return key == "file" || (key.size() > 5 && key.compare(key.size() - 5, 5, "_file") == 0);
}

Value withCanonicalFiles(Value params, const std::filesystem::path& baseDir) {
    forEachFileIn(params, [&baseDir](Value& file) {
        std::filesystem::path p(file.toString());
        if (p.empty()) return;
        if (p.is_relative() && !baseDir.empty()) p = baseDir / p;
        std::error_code ec;
        std::filesystem::path c = std::filesystem::weakly_canonical(p, ec);
        if (ec) c = std::filesystem::absolute(p, ec).lexically_normal();
        if (!ec) file = Value(c.string());
    });
    return params;
}

} // namespace sylva::graph
