#include "engine/export/usd/usdmesh.h"

#include "engine/export/usd/usdformat.h"

#include <charconv>
#include <cstring>
#include <limits>
#include <set>
#include <unordered_map>

namespace sylva::exporter::usd {

namespace {

void indent(std::string& out, int n) {
    out.append(static_cast<std::size_t>(n), ' ');
}

/// The elements of an array, element(0) … element(count - 1), comma-joined without spaces (a
/// mesh array's text: most of a forest's bytes).
template <class Element> void appendJoined(std::string& out, std::size_t count, Element&& element) {
    for (std::size_t k = 0; k < count; ++k) {
        if (k) out += ',';
        element(k);
    }
}

/// Closes a primvar's array and states its interpolation, at indent \p a.
void closePrimvar(std::string& out, int a, const char* interpolation) {
    out += "] (\n";
    indent(out, a + 4);
    out += "interpolation = \"";
    out += interpolation;
    out += "\"\n";
    indent(out, a);
    out += ")\n";
}

} // namespace

std::vector<mesh::Submesh> materialRuns(const mesh::Mesh& m) {
    if (!m.submeshes.empty()) return m.submeshes;
    mesh::Submesh all;
    all.material = "bark";
    all.indexCount = static_cast<std::uint32_t>(m.indices.size());
    return {all};
}

std::size_t appendMeshPrims(std::string& out, const mesh::Mesh& m, int at, bool compact,
                            const MaterialPathOf& materialPath, double cameraDistance) {
    std::size_t written = 0;
    // A 4K frame's pixel is ~2.3e-4 of the distance wide (50° field of view): 0.1 mm is a
    // twentieth of it at 20 m, 1 mm at 200 m, 1 cm at 2 km. A tree meshed for a far camera has
    // lost finer detail than that to its level of detail already.
    const int far = cameraDistance >= 1000.0 ? 2 : cameraDistance >= 100.0 ? 1 : 0;
    const int pd = compact ? 4 - far : 0, nd = compact ? (far ? 2 : 3) : 0,
              ud = compact ? (far ? 3 : 4) : 0;
    auto number = [&](float v, int decimals) {
        if (decimals > 0)
            appendFixed(out, v, decimals);
        else
            appendFloat(out, v);
    };
    auto vec3 = [&](const glm::vec3& v, int decimals) {
        out += '(';
        number(v.x, decimals);
        out += ',';
        number(v.y, decimals);
        out += ',';
        number(v.z, decimals);
        out += ')';
    };
    // Mesh arrays are most of a forest's bytes: their elements go without spaces ("(x,y,z),"),
    // 10-13 % less to write and read; everything else is laid out for people.
    std::vector<std::uint32_t> remap(m.positions.size(), std::numeric_limits<std::uint32_t>::max());
    // About what the text takes (a vertex ~60 bytes, an index ~7): one allocation, no regrowth.
    out.reserve(out.size() + m.positions.size() * 64 + m.indices.size() * 8 + 4096);
    std::vector<std::uint32_t> used;
    struct Face {
        std::uint32_t first; ///< its first triangle's first index
        std::uint32_t count; ///< 3, or 4: a quad whose fourth corner is `fourth`
        std::uint32_t fourth;
    };
    std::vector<Face> faces;
    std::unordered_map<std::uint64_t, std::uint32_t> stIndex; ///< a uv's bits → its place
    std::vector<glm::vec2> stValues;
    std::set<std::string> names;
    for (const mesh::Submesh& run : materialRuns(m)) {
        if (run.indexCount < 3) continue;
        // Each material run is a Mesh of its own with only the vertices it uses, so that a
        // binding needs no face subsets (a forest's leaf runs have a million faces).
        used.clear();
        const std::uint32_t end = run.firstIndex + run.indexCount;
        for (std::uint32_t i = run.firstIndex; i < end; ++i) {
            const std::uint32_t v = m.indices[i];
            if (remap[v] == std::numeric_limits<std::uint32_t>::max()) {
                remap[v] = static_cast<std::uint32_t>(used.size());
                used.push_back(v);
            }
        }
        std::string name = primName(run.material.empty() ? "mesh" : run.material);
        for (int k = 2; !names.insert(name).second; ++k)
            name = primName(run.material) + "_" + std::to_string(k);
        const std::string material = materialPath(run);
        // Leaf cards and the impostor's card are seen from both sides.
        const bool leaf = run.material == "leaf" || run.material == "impostor";

        indent(out, at);
        out += "def Mesh \"" + name + "\" (\n";
        indent(out, at + 4);
        out += "prepend apiSchemas = [\"MaterialBindingAPI\"]\n";
        indent(out, at);
        out += ")\n";
        indent(out, at);
        out += "{\n";
        const int a = at + 4;
        indent(out, a);
        out += leaf || m.cameraRibbons ? "uniform bool doubleSided = 1\n"
                                       : "uniform bool doubleSided = 0\n";
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (std::uint32_t v : used) {
            lo = glm::min(lo, m.positions[v]);
            hi = glm::max(hi, m.positions[v]);
        }
        indent(out, a);
        out += "float3[] extent = [";
        vec3(lo, pd);
        out += ", ";
        vec3(hi, pd);
        out += "]\n";
        // Faces: a triangle pair (a,b,c),(a,c,d), as tubes and leaf cards are made, is written
        // as the quad (a,b,c,d): 4 indices and one count instead of 6 and two (a third of the
        // index text). Renderers triangulate a quad as a fan from its first corner, which gives
        // back the same two triangles.
        faces.clear();
        const std::uint32_t end3 = run.firstIndex + run.indexCount / 3 * 3;
        for (std::uint32_t i = run.firstIndex; i < end3; i += 3) {
            const std::uint32_t* t = &m.indices[i];
            if (i + 6 <= end3) {
                const std::uint32_t* u = t + 3;
                if (u[0] == t[0] && u[1] == t[2] && u[2] != t[0] && u[2] != t[1] && u[2] != t[2]) {
                    faces.push_back({i, 4, u[2]});
                    i += 3;
                    continue;
                }
            }
            faces.push_back({i, 3, 0});
        }
        indent(out, a);
        out += "int[] faceVertexCounts = [";
        appendJoined(out, faces.size(),
                     [&](std::size_t f) { out += faces[f].count == 4 ? '4' : '3'; });
        out += "]\n";
        indent(out, a);
        out += "int[] faceVertexIndices = [";
        char buf[16];
        auto index = [&](std::uint32_t v) {
            out.append(buf, std::to_chars(buf, buf + sizeof buf, remap[v]).ptr);
        };
        appendJoined(out, faces.size(), [&](std::size_t f) {
            const std::uint32_t* t = &m.indices[faces[f].first];
            index(t[0]);
            out += ',';
            index(t[1]);
            out += ',';
            index(t[2]);
            if (faces[f].count == 4) {
                out += ',';
                index(faces[f].fourth);
            }
        });
        out += "]\n";
        // A primvar with one value per face where every face's corners agree (`uniform`: a
        // leaf card is flat and one colour, a quarter of the text), else one per vertex.
        auto facesFlat = [&](const auto& values) {
            for (const Face& face : faces) {
                const std::uint32_t* t = &m.indices[face.first];
                const auto& v0 = values[t[0]];
                if (!(values[t[1]] == v0 && values[t[2]] == v0 &&
                      (face.count == 3 || values[face.fourth] == v0)))
                    return false;
            }
            return true;
        };
        auto faceOrVertexValues = [&](bool flat, const auto& value) {
            if (flat)
                appendJoined(out, faces.size(),
                             [&](std::size_t f) { value(m.indices[faces[f].first]); });
            else
                appendJoined(out, used.size(), [&](std::size_t k) { value(used[k]); });
            closePrimvar(out, a, flat ? "uniform" : "vertex");
        };
        indent(out, a);
        out += "rel material:binding = <" + material + ">\n";
        if (m.normals.size() == m.positions.size()) {
            // Flat faces (leaf cards: one normal at all four corners) get one normal per face.
            indent(out, a);
            out += "normal3f[] normals = [";
            faceOrVertexValues(facesFlat(m.normals),
                               [&](std::uint32_t v) { vec3(m.normals[v], nd); });
        }
        if (m.colors.size() == m.positions.size()) {
            // Leaf tints (Mesh::colors) as displayColor, linear as USD's colours are; only on
            // a run that has any (bark is white). A card is one face of one colour.
            bool tinted = false;
            for (std::uint32_t v : used)
                tinted = tinted || m.colors[v] != glm::u8vec4(255);
            if (tinted) {
                indent(out, a);
                out += "color3f[] primvars:displayColor = [";
                faceOrVertexValues(facesFlat(m.colors), [&](std::uint32_t v) {
                    const glm::u8vec4 c = m.colors[v];
                    out += '(';
                    appendFixed(out, c.x / 255.0f, 3);
                    out += ',';
                    appendFixed(out, c.y / 255.0f, 3);
                    out += ',';
                    appendFixed(out, c.z / 255.0f, 3);
                    out += ')';
                });
            }
        }
        indent(out, a);
        out += "point3f[] points = [";
        appendJoined(out, used.size(), [&](std::size_t k) { vec3(m.positions[used[k]], pd); });
        out += "]\n";
        if (m.uvs.size() == m.positions.size()) {
            // Leaf cards take their corners from a few cells of the leaf atlas: an indexed
            // primvar (the distinct values once, an index per vertex) is ~1/6 of the text.
            stIndex.clear();
            stValues.clear();
            auto uvKey = [](const glm::vec2& uv) {
                std::uint64_t key = 0;
                std::memcpy(&key, &uv, sizeof uv);
                return key;
            };
            for (std::size_t k = 0; k < used.size() && stValues.size() * 4 <= used.size(); ++k) {
                const glm::vec2 uv = m.uvs[used[k]];
                if (stIndex.emplace(uvKey(uv), static_cast<std::uint32_t>(stValues.size())).second)
                    stValues.push_back(uv);
            }
            const bool indexed = stValues.size() * 4 <= used.size();
            auto uvText = [&](const glm::vec2& uv) {
                out += '(';
                number(uv.x, ud);
                out += ',';
                number(uv.y, ud);
                out += ')';
            };
            indent(out, a);
            out += "texCoord2f[] primvars:st = [";
            if (indexed)
                appendJoined(out, stValues.size(), [&](std::size_t k) { uvText(stValues[k]); });
            else
                appendJoined(out, used.size(), [&](std::size_t k) { uvText(m.uvs[used[k]]); });
            closePrimvar(out, a, "vertex");
            if (indexed) {
                indent(out, a);
                out += "int[] primvars:st:indices = [";
                appendJoined(out, used.size(), [&](std::size_t k) {
                    const std::uint32_t i = stIndex.at(uvKey(m.uvs[used[k]]));
                    out.append(buf, std::to_chars(buf, buf + sizeof buf, i).ptr);
                });
                out += "]\n";
            }
        }
        indent(out, a);
        out += "uniform token subdivisionScheme = \"none\"\n";
        indent(out, at);
        out += "}\n";
        for (std::uint32_t v : used)
            remap[v] = std::numeric_limits<std::uint32_t>::max();
        ++written;
    }
    return written;
}

void appendMaterialScope(std::string& out, const std::string& scopePath,
                         const std::vector<std::pair<std::string, const Material*>>& sorted) {
    out += "    def Scope \"Materials\"\n    {\n";
    for (const auto& [prim, m] : sorted) {
        const std::string path = scopePath + "/" + prim;
        const bool textured = !m->diffuseTexture.empty();
        out += "        def Material \"" + prim + "\"\n        {\n";
        out += "            token outputs:surface.connect = <" + path +
               "/Surface.outputs:surface>\n\n";
        out += "            def Shader \"Surface\"\n            {\n";
        out += "                uniform token info:id = \"UsdPreviewSurface\"\n";
        if (textured) {
            out += "                color3f inputs:diffuseColor.connect = <" + path +
                   "/Diffuse.outputs:rgb>\n";
        } else {
            out += "                color3f inputs:diffuseColor = (";
            appendFixed(out, m->diffuse.x, 4);
            out += ", ";
            appendFixed(out, m->diffuse.y, 4);
            out += ", ";
            appendFixed(out, m->diffuse.z, 4);
            out += ")\n";
        }
        out += "                float inputs:metallic = 0\n";
        if (textured && m->alphaMask) {
            out +=
                "                float inputs:opacity.connect = <" + path + "/Diffuse.outputs:a>\n";
            out += "                float inputs:opacityThreshold = 0.5\n";
        }
        // The species' maps (docs/geometry.md): a tangent-space normal map, OpenGL's +Y up as
        // UsdPreviewSurface expects, and a grey roughness map; a constant where there is none.
        const bool normalMap = textured && !m->normalTexture.empty();
        const bool roughnessMap = textured && !m->roughnessTexture.empty();
        if (normalMap)
            out += "                normal3f inputs:normal.connect = <" + path +
                   "/Normal.outputs:rgb>\n";
        if (roughnessMap)
            out += "                float inputs:roughness.connect = <" + path +
                   "/Roughness.outputs:r>\n";
        else
            out += m->twoSided ? "                float inputs:roughness = 0.6\n"
                               : "                float inputs:roughness = 0.9\n";
        out += "                token outputs:surface\n            }\n";
        if (textured) {
            out += "\n            def Shader \"Diffuse\"\n            {\n";
            out += "                uniform token info:id = \"UsdUVTexture\"\n";
            out += "                float4 inputs:fallback = (";
            appendFixed(out, m->diffuse.x, 4);
            out += ", ";
            appendFixed(out, m->diffuse.y, 4);
            out += ", ";
            appendFixed(out, m->diffuse.z, 4);
            out += ", 1)\n";
            out += "                asset inputs:file = @" + m->diffuseTexture + "@\n";
            out += "                token inputs:sourceColorSpace = \"sRGB\"\n";
            out += "                float2 inputs:st.connect = <" + path + "/St.outputs:result>\n";
            out += "                token inputs:wrapS = \"repeat\"\n";
            out += "                token inputs:wrapT = \"repeat\"\n";
            out += "                float outputs:a\n                float3 outputs:rgb\n";
            out += "            }\n";
            // Data maps are read raw; the normal map's 0..1 becomes -1..1.
            auto dataMap = [&](const char* shader, const std::string& file, bool normal) {
                out += std::string("\n            def Shader \"") + shader + "\"\n            {\n";
                out += "                uniform token info:id = \"UsdUVTexture\"\n";
                out += "                asset inputs:file = @" + file + "@\n";
                out += "                token inputs:sourceColorSpace = \"raw\"\n";
                if (normal) {
                    out += "                float4 inputs:scale = (2, 2, 2, 1)\n";
                    out += "                float4 inputs:bias = (-1, -1, -1, 0)\n";
                }
                out +=
                    "                float2 inputs:st.connect = <" + path + "/St.outputs:result>\n";
                out += "                token inputs:wrapS = \"repeat\"\n";
                out += "                token inputs:wrapT = \"repeat\"\n";
                out += normal ? "                float3 outputs:rgb\n"
                              : "                float outputs:r\n";
                out += "            }\n";
            };
            if (normalMap) dataMap("Normal", m->normalTexture, true);
            if (roughnessMap) dataMap("Roughness", m->roughnessTexture, false);
            out += "\n            def Shader \"St\"\n            {\n";
            out += "                uniform token info:id = \"UsdPrimvarReader_float2\"\n";
            out += "                string inputs:varname = \"st\"\n";
            out += "                float2 outputs:result\n            }\n";
        }
        out += "        }\n";
    }
    out += "    }\n";
}

} // namespace sylva::exporter::usd
