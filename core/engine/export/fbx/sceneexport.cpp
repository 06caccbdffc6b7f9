#include "engine/export/fbx/sceneexport.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <unordered_map>

#include <assimp/Exporter.hpp>
#include <assimp/GltfMaterial.h>
#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>

#include "engine/export/fbx/fbxfix.h"
#include "engine/export/formats.h"
#include "engine/export/obj/objwriter.h"
#include "engine/mesh/leaftint.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

namespace sylva::exporter {

namespace {

aiMaterial* makeMaterial(const Material& m) {
    auto* mat = new aiMaterial();
    const aiString name(m.name);
    mat->AddProperty(&name, AI_MATKEY_NAME);
    const aiColor3D diffuse(m.diffuse.x, m.diffuse.y, m.diffuse.z);
    mat->AddProperty(&diffuse, 1, AI_MATKEY_COLOR_DIFFUSE);
    const aiColor4D base(m.diffuse.x, m.diffuse.y, m.diffuse.z, 1.0f);
    mat->AddProperty(&base, 1, AI_MATKEY_BASE_COLOR);
    if (!m.diffuseTexture.empty()) {
        const aiString tex(m.diffuseTexture);
        mat->AddProperty(&tex, AI_MATKEY_TEXTURE_DIFFUSE(0));
        mat->AddProperty(&tex, AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0));
    }
    if (!m.normalTexture.empty()) {
        const aiString tex(m.normalTexture);
        mat->AddProperty(&tex, AI_MATKEY_TEXTURE_NORMALS(0));
    }
    if (!m.roughnessTexture.empty()) {
        const aiString tex(m.roughnessTexture);
        mat->AddProperty(&tex, AI_MATKEY_TEXTURE(aiTextureType_DIFFUSE_ROUGHNESS, 0));
    }
    const int twoSided = m.twoSided ? 1 : 0;
    mat->AddProperty(&twoSided, 1, AI_MATKEY_TWOSIDED);
    if (m.alphaMask) {
        const aiString mode("MASK");
        mat->AddProperty(&mode, AI_MATKEY_GLTF_ALPHAMODE);
    }
    return mat;
}

// One Assimp mesh for the triangles [first, first+count) of \p m, with its vertices compacted.
aiMesh* makeMesh(const mesh::Mesh& m, std::uint32_t first, std::uint32_t count,
                 unsigned materialIndex, const std::string& name, bool srgbColors) {
    auto* out = new aiMesh();
    out->mName = aiString(name);
    out->mMaterialIndex = materialIndex;
    out->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    std::vector<std::uint32_t> remap(m.positions.size(), UINT32_MAX);
    std::vector<std::uint32_t> used;
    for (std::uint32_t i = first; i < first + count; ++i) {
        const std::uint32_t v = m.indices[i];
        if (remap[v] == UINT32_MAX) {
            remap[v] = static_cast<std::uint32_t>(used.size());
            used.push_back(v);
        }
    }
    const auto nv = static_cast<unsigned>(used.size());
    out->mNumVertices = nv;
    out->mVertices = new aiVector3D[nv];
    const bool normals = m.normals.size() == m.positions.size();
    const bool uvs = m.uvs.size() == m.positions.size();
    if (normals) out->mNormals = new aiVector3D[nv];
    if (uvs) {
        out->mTextureCoords[0] = new aiVector3D[nv];
        out->mNumUVComponents[0] = 2;
    }
    // Leaf tints: as sRGB for FBX, what its readers take a vertex colour for (Blender's
    // importer stores them as byte colours, which it reads as sRGB; Maya and Unreal do the
    // same); linear for glTF, whose COLOR_0 is linear.
    const bool colors = m.colors.size() == m.positions.size();
    if (colors) out->mColors[0] = new aiColor4D[nv];
    for (unsigned k = 0; k < nv; ++k) {
        const std::uint32_t v = used[k];
        out->mVertices[k] = aiVector3D(m.positions[v].x, m.positions[v].y, m.positions[v].z);
        if (normals) out->mNormals[k] = aiVector3D(m.normals[v].x, m.normals[v].y, m.normals[v].z);
        if (uvs) out->mTextureCoords[0][k] = aiVector3D(m.uvs[v].x, m.uvs[v].y, 0.0f);
        if (colors) {
            const glm::u8vec4 c = m.colors[v];
            out->mColors[0][k] =
                srgbColors ? aiColor4D(mesh::srgbFromByte(c.x), mesh::srgbFromByte(c.y),
                                       mesh::srgbFromByte(c.z), c.w / 255.0f)
                           : aiColor4D(c.x / 255.0f, c.y / 255.0f, c.z / 255.0f, c.w / 255.0f);
        }
    }
    out->mNumFaces = count / 3;
    out->mFaces = new aiFace[out->mNumFaces];
    for (unsigned f = 0; f < out->mNumFaces; ++f) {
        aiFace& face = out->mFaces[f];
        face.mNumIndices = 3;
        face.mIndices = new unsigned[3];
        for (unsigned c = 0; c < 3; ++c)
            face.mIndices[c] = remap[m.indices[first + 3 * f + c]];
    }
    return out;
}

// The texture's bytes as an embedded Assimp texture (compressed: mHeight 0, the PNG as is);
// nullptr when the file cannot be read (the material then keeps its file reference).
aiTexture* embeddedTexture(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return nullptr;
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.empty()) return nullptr;
    auto* tex = new aiTexture();
    tex->mWidth = static_cast<unsigned>(bytes.size());
    tex->mHeight = 0;
    // The format hint is the extension without its dot, lower case ("png", "jpg").
    const std::string ext = file.extension().string();
    std::size_t n = 0;
    for (std::size_t i = 1; i < ext.size() && n + 1 < HINTMAXTEXTURELEN; ++i)
        tex->achFormatHint[n++] =
            static_cast<char>(std::tolower(static_cast<unsigned char>(ext[i])));
    tex->achFormatHint[n] = '\0';
    tex->pcData = reinterpret_cast<aiTexel*>(new unsigned char[bytes.size()]);
    std::memcpy(tex->pcData, bytes.data(), bytes.size());
    tex->mFilename = aiString(file.filename().string());
    return tex;
}

std::unique_ptr<aiScene> buildScene(const SceneDesc& desc, bool embedTextures, bool srgbColors) {
    auto scene = std::make_unique<aiScene>();
    std::vector<Material> materials = desc.materials;
    std::unordered_map<std::string, unsigned> materialIndex;
    for (unsigned i = 0; i < materials.size(); ++i)
        materialIndex[materials[i].name] = i;

    std::vector<aiMesh*> meshes;
    std::vector<std::vector<unsigned>> meshParts(desc.meshes.size());
    for (std::size_t mi = 0; mi < desc.meshes.size(); ++mi) {
        const SceneMesh& sm = desc.meshes[mi];
        if (!sm.mesh) throw InvalidInput("scene mesh '" + sm.name + "' has no mesh");
        std::vector<mesh::Submesh> parts = sm.mesh->submeshes;
        if (parts.empty())
            parts.push_back({"bark", 0, static_cast<std::uint32_t>(sm.mesh->indices.size())});
        for (const mesh::Submesh& part : parts) {
            if (part.indexCount == 0) continue;
            const std::string name = materialName(part);
            auto it = materialIndex.find(name);
            if (it == materialIndex.end()) {
                // A material nobody described still gets a plain entry so nothing is dropped.
                materials.push_back({name, glm::vec3(0.8f), "", false, false});
                it = materialIndex.emplace(name, static_cast<unsigned>(materials.size() - 1)).first;
            }
            meshParts[mi].push_back(static_cast<unsigned>(meshes.size()));
            meshes.push_back(makeMesh(*sm.mesh, part.firstIndex, part.indexCount, it->second,
                                      sm.name + "_" + part.material, srgbColors));
        }
    }
    scene->mNumMeshes = static_cast<unsigned>(meshes.size());
    scene->mMeshes = new aiMesh*[std::max<std::size_t>(meshes.size(), 1)];
    std::copy(meshes.begin(), meshes.end(), scene->mMeshes);

    if (embedTextures) {
        // Each texture file once; the materials name it "*<index>" (Assimp's embedded form).
        std::vector<aiTexture*> textures;
        std::map<std::string, unsigned> textureIndex;
        for (Material& m : materials)
            for (TextureSlot slot : kTextureSlots) {
                const std::filesystem::path file = textureSourceOf(m, desc.textureSource, slot);
                if (file.empty()) continue;
                auto found = textureIndex.find(file.string());
                if (found == textureIndex.end()) {
                    aiTexture* tex = embeddedTexture(file);
                    if (!tex) {
                        // A map that cannot be read is left out rather than referenced.
                        if (slot != TextureSlot::Diffuse) texturePath(m, slot).clear();
                        continue;
                    }
                    found =
                        textureIndex.emplace(file.string(), static_cast<unsigned>(textures.size()))
                            .first;
                    textures.push_back(tex);
                }
                std::string& path = texturePath(m, slot);
                path = std::to_string(found->second);
                path.insert(path.begin(), '*');
            }
        scene->mNumTextures = static_cast<unsigned>(textures.size());
        if (!textures.empty()) {
            scene->mTextures = new aiTexture*[textures.size()];
            std::copy(textures.begin(), textures.end(), scene->mTextures);
        }
    }

    scene->mNumMaterials = static_cast<unsigned>(materials.size());
    scene->mMaterials = new aiMaterial*[std::max<std::size_t>(materials.size(), 1)];
    for (unsigned i = 0; i < materials.size(); ++i)
        scene->mMaterials[i] = makeMaterial(materials[i]);

    scene->mRootNode = new aiNode("sylva");
    aiNode* root = scene->mRootNode;
    root->mNumChildren = static_cast<unsigned>(desc.instances.size());
    root->mChildren = new aiNode*[std::max<std::size_t>(desc.instances.size(), 1)];
    for (std::size_t i = 0; i < desc.instances.size(); ++i) {
        const SceneInstance& inst = desc.instances[i];
        if (inst.mesh >= desc.meshes.size())
            throw InvalidInput("instance '" + inst.name + "' names mesh " +
                               std::to_string(inst.mesh) + " of " +
                               std::to_string(desc.meshes.size()));
        auto* node = new aiNode(inst.name);
        node->mParent = root;
        const aiMatrix4x4 t(
            aiVector3D(inst.scale.x, inst.scale.y, inst.scale.z),
            aiQuaternion(inst.rotation.w, inst.rotation.x, inst.rotation.y, inst.rotation.z),
            aiVector3D(inst.position.x, inst.position.y, inst.position.z));
        node->mTransformation = t;
        const auto& parts = meshParts[inst.mesh];
        node->mNumMeshes = static_cast<unsigned>(parts.size());
        if (!parts.empty()) {
            node->mMeshes = new unsigned[parts.size()];
            std::copy(parts.begin(), parts.end(), node->mMeshes);
        }
        root->mChildren[i] = node;
    }
    if (desc.decorate) desc.decorate(*scene);
    return scene;
}

} // namespace

SceneFormat sceneFormatFor(const std::filesystem::path& path) {
    const FormatRow& row = formatFor(path);
    switch (row.format) {
    case Format::Glb:
        return SceneFormat::Glb;
    case Format::Gltf:
        return SceneFormat::Gltf;
    case Format::Fbx:
        return SceneFormat::Fbx;
    case Format::Obj:
    case Format::Usda:
        break;
    }
    throw InvalidInput(std::string("Assimp's exporter writes no ") + row.name + " ('" +
                       row.extension + "'; use .glb, .gltf or .fbx)");
}

namespace {

// A growable in-memory file that Assimp's exporters can write, seek and overwrite.
class MemoryStream : public Assimp::IOStream {
public:
    explicit MemoryStream(std::string& bytes) : mBytes(bytes) {}
    size_t Read(void*, size_t, size_t) override { return 0; } // export only
    size_t Write(const void* buffer, size_t size, size_t count) override {
        const std::size_t n = size * count;
        if (mPos + n > mBytes.size()) mBytes.resize(mPos + n);
        std::memcpy(mBytes.data() + mPos, buffer, n);
        mPos += n;
        return count;
    }
    aiReturn Seek(size_t offset, aiOrigin origin) override {
        const std::size_t base = origin == aiOrigin_SET   ? 0
                                 : origin == aiOrigin_CUR ? mPos
                                                          : mBytes.size();
        if (base + offset > mBytes.size()) return aiReturn_FAILURE;
        mPos = base + offset;
        return aiReturn_SUCCESS;
    }
    size_t Tell() const override { return mPos; }
    size_t FileSize() const override { return mBytes.size(); }
    void Flush() override {}

private:
    std::string& mBytes;
    std::size_t mPos = 0;
};

// The files an exporter opens for writing, kept in memory by name.
class MemoryFiles : public Assimp::IOSystem {
public:
    bool Exists(const char* file) const override { return mFiles.count(file) != 0; }
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        if (mode == nullptr || (mode[0] != 'w' && mode[0] != 'a')) return nullptr;
        std::string& bytes = mFiles[file];
        if (mode[0] == 'w') bytes.clear();
        return new MemoryStream(bytes);
    }
    void Close(Assimp::IOStream* stream) override { delete stream; }
    std::string take(const std::string& file) { return std::move(mFiles[file]); }

private:
    std::map<std::string, std::string> mFiles;
};

} // namespace

namespace {

// What Assimp's exporter made: the main file and, for a text glTF, its buffer.
struct ExportResult {
    std::string first, second;
    std::string secondName; ///< Assimp's name of the second blob ("bin")
    std::string error;
};

// Runs Assimp's exporter over a scene it owns. Assimp has no cancellation and its exporters
// can run for minutes on a large scene, so it runs on a thread of its own that the caller may
// abandon: it touches nothing but this job (its own copy of the scene, in-memory files), and
// the job lives as long as the thread.
struct ExportJob {
    std::unique_ptr<aiScene> scene;
    SceneFormat format = SceneFormat::Glb;
    ExportResult result;
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;

    void run() {
        try {
            const char* id = format == SceneFormat::Glb        ? "glb2"
                             : format == SceneFormat::Gltf     ? "gltf2"
                             : format == SceneFormat::FbxAscii ? "fbxa"
                                                               : "fbx";
            Assimp::Exporter exporter;
            if (format == SceneFormat::Fbx || format == SceneFormat::FbxAscii) {
                // Assimp's FBX writer seeks back to patch block offsets, which its export blobs
                // do not support: it writes into a seekable in-memory file instead.
                auto* files = new MemoryFiles; // owned by the exporter from here on
                exporter.SetIOHandler(files);
                if (exporter.Export(scene.get(), id, "scene.fbx") != AI_SUCCESS)
                    result.error = exporter.GetErrorString();
                else
                    result.first = files->take("scene.fbx");
            } else if (const aiExportDataBlob* blob = exporter.ExportToBlob(scene.get(), id)) {
                result.first.assign(static_cast<const char*>(blob->data), blob->size);
                if (blob->next) {
                    result.second.assign(static_cast<const char*>(blob->next->data),
                                         blob->next->size);
                    result.secondName = blob->next->name.C_Str();
                }
            } else {
                result.error = exporter.GetErrorString();
            }
        } catch (const std::exception& e) {
            result.error = e.what();
        } catch (...) {
            result.error = "unknown error in Assimp's exporter";
        }
        scene.reset();
        const std::lock_guard<std::mutex> lock(mutex);
        done = true;
        finished.notify_all();
    }
};

// Writes \p bytes atomically in slices, checking \p progress between them.
void writeFileCancellable(const std::filesystem::path& path, std::string_view bytes,
                          Progress& progress) {
    constexpr std::size_t kSlice = std::size_t(16) << 20;
    AtomicFile file(path);
    for (std::size_t at = 0; at < bytes.size(); at += kSlice) {
        progress.checkCancelled();
        file.write(bytes.substr(at, kSlice));
    }
    progress.checkCancelled();
    file.commit();
}

} // namespace

void writeScene(const std::filesystem::path& path, const SceneDesc& desc, SceneFormat format,
                Progress& progress) {
    // A .glb and an .fbx are single files: their textures go inside. A text glTF keeps
    // references to the textures/ folder beside it.
    auto job = std::make_shared<ExportJob>();
    job->scene = buildScene(desc, format != SceneFormat::Gltf,
                            format == SceneFormat::Fbx || format == SceneFormat::FbxAscii);
    job->format = format;
    progress.checkCancelled();
    std::thread worker([job] { job->run(); });
    {
        std::unique_lock<std::mutex> lock(job->mutex);
        while (!job->finished.wait_for(lock, std::chrono::milliseconds(50),
                                       [&] { return job->done; })) {
            if (progress.isCancelled()) {
                // Abandoned: the thread finishes (or dies with the process) on its own data;
                // nothing was written to disk yet.
                lock.unlock();
                worker.detach();
                throw Cancelled();
            }
        }
    }
    worker.join();
    ExportResult& result = job->result;
    if (!result.error.empty())
        throw IoError("cannot export " + path.string() + ": " + result.error);
    progress.checkCancelled();
    if (format == SceneFormat::Fbx || format == SceneFormat::FbxAscii) {
        // The binary is repaired, both forms get their unit, before they are written.
        FbxRepairOptions repair;
        repair.frameRate = desc.animationFrameRate;
        repair.animationSeconds = desc.animationSeconds;
        writeFileCancellable(path,
                             format == SceneFormat::Fbx
                                 ? repairAssimpFbxBinary(result.first, repair)
                                 : setFbxAsciiUnitScale(std::move(result.first)),
                             progress);
        return;
    }
    // A text glTF comes as the .gltf blob followed by its .bin, which the text references by
    // Assimp's blob placeholder ("$blobfile.bin"); we name it after the file instead.
    std::string& first = result.first;
    if (format == SceneFormat::Gltf && !result.secondName.empty()) {
        const std::string binName = path.stem().string() + ".bin";
        const std::string assimpBin = std::string("$blobfile.") + result.secondName;
        for (std::size_t at = first.find(assimpBin); at != std::string::npos;
             at = first.find(assimpBin, at + binName.size()))
            first.replace(at, assimpBin.size(), binName);
        writeFileCancellable(path.parent_path() / binName, result.second, progress);
    }
    writeFileCancellable(path, first, progress);
}

namespace {
void number(std::string& out, double v) {
    char buf[48];
    out.append(buf, formatFixed(buf, v, 6));
}
std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;
        out += c;
    }
    return out + "\"";
}
} // namespace

std::string formatInstancesJson(const SceneDesc& scene) {
    std::string out = "{\"format\":\"sylva-instances\",\"format_version\":1,\"instances\":[";
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const SceneInstance& in = scene.instances[i];
        if (i) out += ',';
        out += "\n{\"name\":" + jsonString(in.name) + ",\"mesh\":" +
               jsonString(in.mesh < scene.meshes.size() ? scene.meshes[in.mesh].name : "") +
               ",\"position\":[";
        const float vals[10] = {in.position.x, in.position.y, in.position.z, in.rotation.x,
                                in.rotation.y, in.rotation.z, in.rotation.w, in.scale.x,
                                in.scale.y,    in.scale.z};
        for (int k = 0; k < 10; ++k) {
            if (k == 3)
                out += "],\"rotation\":[";
            else if (k == 7)
                out += "],\"scale\":[";
            else if (k)
                out += ',';
            number(out, vals[k]);
        }
        out += "]}";
    }
    out += "\n]}\n";
    return out;
}

std::string formatInstancesCsv(const SceneDesc& scene) {
    std::string out = "name,mesh,px,py,pz,qx,qy,qz,qw,sx,sy,sz\n";
    for (const SceneInstance& in : scene.instances) {
        out += in.name + "," + (in.mesh < scene.meshes.size() ? scene.meshes[in.mesh].name : "");
        const float vals[10] = {in.position.x, in.position.y, in.position.z, in.rotation.x,
                                in.rotation.y, in.rotation.z, in.rotation.w, in.scale.x,
                                in.scale.y,    in.scale.z};
        for (float v : vals) {
            out += ',';
            number(out, v);
        }
        out += '\n';
    }
    return out;
}

} // namespace sylva::exporter
