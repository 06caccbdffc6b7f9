#include "engine/util/atomicfile.h"

#include "engine/util/error.h"

#include <cerrno>
#include <cstring>
#include <random>
#include <unistd.h>

namespace sylva {

namespace {
std::filesystem::path temporaryBeside(const std::filesystem::path& path) {
    // The temporary lives in the target folder so that rename() stays on one file system.
    std::random_device rd;
    // Built by appending: GCC 12 reports a false -Wrestrict on "." + std::string&&.
    std::string name(1, '.');
    name.append(path.filename().string());
    name.append(".tmp");
    name.append(std::to_string(::getpid()));
    name.push_back('-');
    name.append(std::to_string(rd()));
    return path.parent_path() / name;
}
} // namespace

AtomicFile::AtomicFile(std::filesystem::path path, Durability durability)
    : mPath(std::move(path)), mDurability(durability) {
    mTemp = temporaryBeside(mPath);
    mFile = std::fopen(mTemp.c_str(), "wb");
    if (!mFile) throw IoError("cannot write " + mPath.string() + ": " + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
    if (mFile) std::fclose(mFile);
    if (!mCommitted) {
        std::error_code ec;
        std::filesystem::remove(mTemp, ec);
    }
}

void AtomicFile::write(std::string_view bytes) {
    if (bytes.empty()) return;
    if (std::fwrite(bytes.data(), 1, bytes.size(), mFile) != bytes.size())
        throw IoError("cannot write " + mPath.string() + ": " + std::strerror(errno));
}

int AtomicFile::flushedDescriptor() {
    if (std::fflush(mFile) != 0)
        throw IoError("cannot write " + mPath.string() + ": " + std::strerror(errno));
    return ::fileno(mFile);
}

void AtomicFile::commit() {
    if (std::fflush(mFile) != 0 ||
        (mDurability == Durability::Durable && ::fsync(::fileno(mFile)) != 0)) {
        throw IoError("cannot write " + mPath.string() + ": " + std::strerror(errno));
    }
    const int rc = std::fclose(mFile);
    mFile = nullptr;
    if (rc != 0) throw IoError("cannot write " + mPath.string() + ": " + std::strerror(errno));
    std::error_code ec;
    std::filesystem::rename(mTemp, mPath, ec);
    if (ec) throw IoError("cannot replace " + mPath.string() + ": " + ec.message());
    mCommitted = true;
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
    AtomicFile file(path);
    file.write(bytes);
    file.commit();
}

} // namespace sylva
