#pragma once

#include <string>
#include <vector>

namespace sylva::cli {

// Each command takes its arguments (without the command name) and returns the exit status.
// They throw UsageError, sylva::InvalidInput, sylva::IoError...; main() maps those to messages
// and exit statuses in one place.
int runExpand(const std::vector<std::string>& args);
int runTree(const std::vector<std::string>& args);
int runForest(const std::vector<std::string>& args);
int runCompose(const std::vector<std::string>& args);
int runStats(const std::vector<std::string>& args);
int runLods(const std::vector<std::string>& args);
int runNodes(const std::vector<std::string>& args);

} // namespace sylva::cli
