#include "engine/export/usd/usdstagewriter.h"

#include "engine/export/usd/usdformat.h"
#include "engine/export/usd/usdmesh.h"
#include "engine/util/error.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

#include <glm/gtc/quaternion.hpp>

#include <omp.h>

namespace sylva::exporter::usd {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kFlushBytes = std::size_t(8) << 20;
constexpr std::size_t kArrayChunk = 65536; // elements between cancellation checks

void indent(std::string& out, int n) {
    out.append(static_cast<std::size_t>(n), ' ');
}

std::string forestPath() {
    return "/Forest";
}

} // namespace

// Writes buffers to the file on a thread of its own, so that the kernel's copy into the page
// cache (a fifth of the time of a large stage) overlaps the formatting of the next trees. At
// most two buffers wait: memory stays bounded.
struct UsdStageWriter::Background {
    explicit Background(AtomicFile& file) : mFile(file), mThread([this] { run(); }) {}
    ~Background() {
        {
            const std::lock_guard<std::mutex> lock(mMutex);
            mStop = true;
            mQueue.clear(); // abandoned: the temporary is removed after this
        }
        mChanged.notify_all();
        mThread.join();
    }
    void push(std::string bytes) {
        std::unique_lock<std::mutex> lock(mMutex);
        mChanged.wait(lock, [&] { return mQueue.size() < 2 || mError; });
        if (mError) std::rethrow_exception(mError);
        mQueue.push_back(std::move(bytes));
        mChanged.notify_all();
    }
    // Waits until everything queued is written.
    void drain() {
        std::unique_lock<std::mutex> lock(mMutex);
        mChanged.wait(lock, [&] { return (mQueue.empty() && !mBusy) || mError; });
        if (mError) std::rethrow_exception(mError);
    }

private:
    void run() {
        std::unique_lock<std::mutex> lock(mMutex);
        for (;;) {
            mChanged.wait(lock, [&] { return mStop || !mQueue.empty(); });
            if (mStop) return;
            std::string bytes = std::move(mQueue.front());
            mQueue.pop_front();
            mBusy = true;
            lock.unlock();
            std::exception_ptr error;
            try {
                mFile.write(bytes);
            } catch (...) {
                error = std::current_exception();
            }
            std::string().swap(bytes);
            lock.lock();
            mBusy = false;
            if (error) mError = error;
            mChanged.notify_all();
        }
    }

    AtomicFile& mFile;
    std::mutex mMutex;
    std::condition_variable mChanged;
    std::deque<std::string> mQueue;
    bool mBusy = false, mStop = false;
    std::exception_ptr mError;
    std::thread mThread;
};

std::string treePrimName(std::uint64_t id) {
    return "tree_" + std::to_string(id);
}

UsdStageWriter::UsdStageWriter(fs::path path, UsdLayerOptions options)
    : mPath(std::move(path)), mOptions(std::move(options)) {
    if (mOptions.tileCount < 1 || mOptions.tile < 0 || mOptions.tile >= mOptions.tileCount)
        throw InvalidInput("tile " + std::to_string(mOptions.tile + 1) + " of " +
                           std::to_string(mOptions.tileCount) + " does not exist");
    if (const fs::path dir = mPath.parent_path(); !dir.empty()) {
        std::error_code ec;
        fs::create_directories(dir, ec);
        if (ec) throw IoError("cannot create " + dir.string() + ": " + ec.message());
    }
    const std::vector<std::string> species = std::move(mOptions.species);
    mOptions.species.clear();
    for (const std::string& name : species)
        speciesIndex(name);
    mFile = std::make_unique<AtomicFile>(mPath, mOptions.durability);
    mWriter = std::make_unique<Background>(*mFile);

    std::string& out = mBuffer;
    out += "#usda 1.0\n(\n    customLayerData = {\n        string generator = \"Sylva\"\n";
    if (!mOptions.sceneKey.empty())
        out += "        string sylvaScene = " + usdString(mOptions.sceneKey) + "\n";
    out += "        int sylvaTile = " + std::to_string(mOptions.tile + 1) + "\n";
    out += "        int sylvaTiles = " + std::to_string(mOptions.tileCount) + "\n";
    out += "    }\n    defaultPrim = \"Forest\"\n    metersPerUnit = 1\n    upAxis = \"Y\"\n)\n\n";
    out += "def Xform \"Forest\" (\n    kind = \"assembly\"\n)\n{\n";
    out += "    def Xform \"Trees\" (\n        kind = \"group\"\n    )\n    {\n";
}

UsdStageWriter::~UsdStageWriter() = default;

std::uint32_t UsdStageWriter::speciesIndex(const std::string& name) {
    for (std::size_t i = 0; i < mOptions.species.size(); ++i)
        if (mOptions.species[i] == name) return static_cast<std::uint32_t>(i);
    // Prim names unique even where two names map to the same identifier.
    std::string prim = primName(name);
    for (int k = 2;
         std::find(mSpeciesPrims.begin(), mSpeciesPrims.end(), prim) != mSpeciesPrims.end(); ++k)
        prim = primName(name) + "_" + std::to_string(k);
    mOptions.species.push_back(name);
    mSpeciesPrims.push_back(prim);
    mInstances.emplace_back();
    return static_cast<std::uint32_t>(mOptions.species.size() - 1);
}

void UsdStageWriter::setVariants(std::vector<UsdVariant> variants) {
    for (const UsdVariant& v : variants) {
        if (v.species >= mOptions.species.size())
            throw InvalidInput("variant of species " + std::to_string(v.species) +
                               ", the scene has " + std::to_string(mOptions.species.size()));
        if (!v.mesh) throw InvalidInput("variant without a mesh");
    }
    mVariants = std::move(variants);
    // protoIndices count in the order of the instancer's prototypes: the species' variants by
    // their index (which need not be 0..K-1).
    mProtoIndex.assign(mVariants.size(), 0);
    for (std::size_t i = 0; i < mVariants.size(); ++i)
        for (const UsdVariant& other : mVariants)
            if (other.species == mVariants[i].species && other.index < mVariants[i].index)
                ++mProtoIndex[i];
}

const std::string& UsdStageWriter::materialPrim(const mesh::Submesh& submesh) {
    const std::string name = materialName(submesh);
    auto it = mMaterialPrims.find(name);
    if (it != mMaterialPrims.end()) return it->second;
    // The material itself: the species' texture, or Sylva's default bark/leaf.
    if (!submesh.texture.empty()) {
        mesh::Mesh one;
        one.submeshes.push_back(submesh);
        addMaterialsOf(one, mMaterials);
    } else {
        bool found = false;
        for (const Material& m : defaultMaterials())
            if (m.name == name) {
                mMaterials.push_back(m);
                found = true;
            }
        if (!found) mMaterials.push_back({name, glm::vec3(0.5f), "", false, false});
    }
    std::string prim = primName(name);
    for (int k = 2; !mUsedMaterialPrims.insert(prim).second; ++k)
        prim = primName(name) + "_" + std::to_string(k);
    return mMaterialPrims.emplace(name, prim).first->second;
}

std::size_t UsdStageWriter::appendMesh(std::string& out, const mesh::Mesh& m, int at,
                                       double cameraDistance) const {
    return appendMeshPrims(
        out, m, at, mOptions.compact,
        [&](const mesh::Submesh& run) {
            return forestPath() + "/Materials/" + mMaterialPrims.at(materialName(run));
        },
        cameraDistance);
}

void UsdStageWriter::add(const std::vector<UsdTree>& trees, Progress& progress) {
    progress.checkCancelled();
    std::vector<const UsdTree*> unique;
    for (const UsdTree& t : trees) {
        if (t.species >= mInstances.size())
            throw InvalidInput("tree " + std::to_string(t.id) + " of an unknown species");
        if (t.variant < 0) {
            if (!t.mesh) throw InvalidInput("tree " + std::to_string(t.id) + " has no mesh");
            for (const mesh::Submesh& s : materialRuns(*t.mesh))
                materialPrim(s); // named here, in tree order, before the parallel formatting
            unique.push_back(&t);
            continue;
        }
        if (static_cast<std::size_t>(t.variant) >= mVariants.size() ||
            mVariants[static_cast<std::size_t>(t.variant)].species != t.species)
            throw InvalidInput("tree " + std::to_string(t.id) + ": variant " +
                               std::to_string(t.variant) + " is not one of its species'");
        Instances& in = mInstances[t.species];
        in.ids.push_back(t.id);
        in.protoIndices.push_back(mProtoIndex[static_cast<std::size_t>(t.variant)]);
        in.positions.push_back(t.position);
        in.rotations.push_back(t.rotationY);
        in.scales.push_back(t.scale);
        ++mStats.instances;
    }
    std::vector<std::string> texts(unique.size());
    std::vector<std::size_t> meshes(unique.size(), 0);
#pragma omp parallel for schedule(dynamic, 1)
    for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t>(unique.size()); ++k) {
        if (progress.isCancelled()) continue;
        const UsdTree& t = *unique[static_cast<std::size_t>(k)];
        std::string& out = texts[static_cast<std::size_t>(k)];
        out += "        def Xform \"" + treePrimName(t.id) + "\" (\n";
        out += "            kind = \"component\"\n        )\n        {\n";
        out +=
            "            custom string sylva:species = " + usdString(mOptions.species[t.species]) +
            "\n";
        out += "            double3 xformOp:translate = (";
        appendFloat(out, t.position.x);
        out += ", ";
        appendFloat(out, t.position.y);
        out += ", ";
        appendFloat(out, t.position.z);
        out += ")\n            float xformOp:rotateY = ";
        appendFloat(out, static_cast<float>(glm::degrees(static_cast<double>(t.rotationY))));
        out += "\n            float3 xformOp:scale = (";
        for (int c = 0; c < 3; ++c) {
            if (c) out += ", ";
            appendFloat(out, t.scale);
        }
        out += ")\n            uniform token[] xformOpOrder = [\"xformOp:translate\", "
               "\"xformOp:rotateY\", \"xformOp:scale\"]\n\n";
        meshes[static_cast<std::size_t>(k)] = appendMesh(out, *t.mesh, 12, t.cameraDistance);
        out += "        }\n";
    }
    progress.checkCancelled();
    for (std::string& text : texts)
        emit(text);
    mStats.uniqueTrees += unique.size();
    for (std::size_t n : meshes)
        mStats.meshes += n;
}

void UsdStageWriter::flush(bool force) {
    if (!force && mBuffer.size() < kFlushBytes) return;
    std::string full;
    full.reserve(kFlushBytes + kFlushBytes / 4);
    full.swap(mBuffer);
    mWriter->push(std::move(full));
}

void UsdStageWriter::emit(std::string& text) {
    // A tree's or a variant's text is megabytes: handed on whole rather than copied.
    if (text.size() >= kFlushBytes / 4) {
        flush(true);
        mWriter->push(std::move(text));
    } else {
        mBuffer += text;
        flush();
    }
    std::string().swap(text);
}

void UsdStageWriter::writeInstancers(Progress& progress) {
    std::string& out = mBuffer;
    out += "    def Xform \"Instancers\" (\n        kind = \"group\"\n    )\n    {\n";
    const bool tiled = mOptions.tileCount > 1;
    for (std::size_t s = 0; s < mInstances.size(); ++s) {
        const Instances& in = mInstances[s];
        if (in.ids.empty()) continue;
        std::vector<const UsdVariant*> protos;
        for (const UsdVariant& v : mVariants)
            if (v.species == s) protos.push_back(&v);
        std::sort(protos.begin(), protos.end(),
                  [](const UsdVariant* a, const UsdVariant* b) { return a->index < b->index; });
        for (const UsdVariant* v : protos)
            for (const mesh::Submesh& run : materialRuns(*v->mesh))
                materialPrim(run);
        const std::string& species = mSpeciesPrims[s];
        const std::string holder = forestPath() + "/Instancers/" + species;
        // The prototypes live under an `over` (no renderer traverses it: only the instancers
        // draw them). A single run keeps them under its PointInstancer; the tiles of a farm
        // run each carry the same `over` at the single run's path, which composition merges
        // into one set that every tile's instancer points at.
        auto writePrototypes = [&](int at) {
            indent(out, at);
            out += "over \"Prototypes\"\n";
            indent(out, at);
            out += "{\n";
            // Formatted in parallel, a few at a time (a library variant is ~12 MB of text),
            // and written in order.
            const std::size_t step = static_cast<std::size_t>(std::max(1, omp_get_max_threads()));
            for (std::size_t first = 0; first < protos.size(); first += step) {
                const std::size_t n = std::min(step, protos.size() - first);
                std::vector<std::string> texts(n);
                std::vector<std::size_t> meshes(n, 0);
#pragma omp parallel for schedule(dynamic, 1)
                for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t>(n); ++k) {
                    const UsdVariant& v = *protos[first + static_cast<std::size_t>(k)];
                    std::string& text = texts[static_cast<std::size_t>(k)];
                    indent(text, at + 4);
                    text += "def Xform \"variant_" + std::to_string(v.index) + "\" (\n";
                    indent(text, at + 8);
                    text += "kind = \"component\"\n";
                    indent(text, at + 4);
                    text += ")\n";
                    indent(text, at + 4);
                    text += "{\n";
                    meshes[static_cast<std::size_t>(k)] = appendMesh(text, *v.mesh, at + 8);
                    indent(text, at + 4);
                    text += "}\n";
                }
                for (std::size_t k = 0; k < n; ++k) {
                    emit(texts[k]);
                    mStats.meshes += meshes[k];
                }
                progress.checkCancelled();
            }
            indent(out, at);
            out += "}\n";
        };
        std::string instancer = species;
        if (tiled) {
            out += "        over \"" + species + "\"\n        {\n";
            writePrototypes(12);
            out += "        }\n\n";
            instancer += "_tile" + std::to_string(mOptions.tile + 1);
        }
        mStats.prototypes += protos.size();
        ++mStats.instancers;
        out += "        def PointInstancer \"" + instancer + "\"\n        {\n";
        auto array = [&](const char* decl, std::size_t n, auto&& element) {
            out += "            ";
            out += decl;
            out += " = [";
            for (std::size_t i = 0; i < n; ++i) {
                if (i) out += ',';
                element(i);
                if (i % kArrayChunk == kArrayChunk - 1) {
                    flush();
                    progress.checkCancelled();
                }
            }
            out += "]\n";
        };
        char buf[32];
        array("int64[] ids", in.ids.size(), [&](std::size_t i) {
            out.append(buf, std::to_chars(buf, buf + sizeof buf, in.ids[i]).ptr);
        });
        array("quath[] orientations", in.ids.size(), [&](std::size_t i) {
            appendQuath(out, glm::angleAxis(in.rotations[i], glm::vec3(0, 1, 0)));
        });
        array("point3f[] positions", in.ids.size(), [&](std::size_t i) {
            out += '(';
            appendFloat(out, in.positions[i].x);
            out += ',';
            appendFloat(out, in.positions[i].y);
            out += ',';
            appendFloat(out, in.positions[i].z);
            out += ')';
        });
        array("int[] protoIndices", in.ids.size(), [&](std::size_t i) {
            out.append(buf, std::to_chars(buf, buf + sizeof buf, in.protoIndices[i]).ptr);
        });
        out += "            rel prototypes = [";
        for (std::size_t k = 0; k < protos.size(); ++k) {
            if (k) out += ", ";
            out += "<" + holder + "/Prototypes/variant_" + std::to_string(protos[k]->index) + ">";
        }
        out += "]\n";
        array("float3[] scales", in.ids.size(), [&](std::size_t i) {
            out += '(';
            for (int c = 0; c < 3; ++c) {
                if (c) out += ',';
                appendFloat(out, in.scales[i]);
            }
            out += ')';
        });
        if (!tiled) {
            out += '\n';
            writePrototypes(12);
        }
        out += "        }\n";
        flush();
    }
    out += "    }\n\n";
}

void UsdStageWriter::writeMaterials() {
    std::string& out = mBuffer;
    // Sorted by prim name: the order a material was first met depends on the trees, this does not.
    std::vector<std::pair<std::string, const Material*>> sorted;
    for (const Material& m : mMaterials)
        sorted.emplace_back(mMaterialPrims.at(m.name), &m);
    std::sort(sorted.begin(), sorted.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    appendMaterialScope(out, forestPath() + "/Materials", sorted);
    mStats.materials = sorted.size();
}

std::vector<fs::path> UsdStageWriter::commit(Progress& progress) {
    progress.checkCancelled();
    mBuffer += "    }\n\n"; // Trees
    writeInstancers(progress);
    writeMaterials();
    mBuffer += "}\n";
    flush(true);
    progress.checkCancelled();
    std::vector<fs::path> written{mPath};
    // The textures first: when the layer appears, what it references is there.
    const fs::path dir = mPath.parent_path().empty() ? fs::path(".") : mPath.parent_path();
    if (copyTextures(mMaterials, mOptions.shippedTextures, dir) > 0)
        written.push_back(dir / "textures");
    mWriter->drain();
    progress.checkCancelled();
    mFile->commit();
    return written;
}

} // namespace sylva::exporter::usd
