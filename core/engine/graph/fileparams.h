#pragma once

#include <filesystem>
#include <string>

#include "engine/util/value.h"

namespace sylva::graph {

/// Whether a node parameter names a file: `file`, `grammar_file`, `*_file`. The one place that
/// decides it, for path rewriting on Save As, the files an editor watches, and the tree cache's
/// key (which hashes the files, not the folder they were named from).
bool isFileParam(const std::string& key);

/// Calls \p f on every file reference in \p value: string members named as files
/// (isFileParam), also inside nested objects and arrays (a mesh envelope's
/// `{"shape": "mesh", "file": …}`, an adapt node's obstacles).
template <typename V, typename F> void forEachFileIn(V& value, F&& f) {
    if (value.isObject()) {
        for (auto& [key, member] : value.objectRef())
            if (isFileParam(key) && member.isString())
                f(member);
            else
                forEachFileIn(member, f);
    } else if (value.isArray()) {
        for (auto& element : value.arrayRef())
            forEachFileIn(element, f);
    }
}

/// \p params with every file reference made absolute against \p baseDir and spelled one way
/// (symbolic links and `..` resolved where the file exists, lexically otherwise): the same
/// files named from another folder give the same value.
Value withCanonicalFiles(Value params, const std::filesystem::path& baseDir);

} // namespace sylva::graph
