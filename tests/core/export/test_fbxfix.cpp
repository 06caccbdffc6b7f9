// Binary FBX repair (Assimp 5.2.5 output → FBX 7.5 that Blender and Assimp read): hand-built
// records with hand-computed offsets, the unit statement, malformed input, and the structure of
// a real export.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "engine/export/fbx/fbxfix.h"
#include "engine/export/fbx/sceneexport.h"
#include "engine/mesh/mesh.h"
#include "engine/util/error.h"

using namespace sylva;

namespace {

std::string header(std::uint32_t version = 7500) {
    std::string h = "Kaydara FBX Binary  ";
    h.push_back('\0');
    h.push_back('\x1a');
    h.push_back('\0');
    h.append(reinterpret_cast<const char*>(&version), 4);
    return h;
}

void putU64(std::string& s, std::uint64_t v) {
    s.append(reinterpret_cast<const char*>(&v), 8);
}
std::uint64_t u64(const std::string& s, std::size_t at) {
    std::uint64_t v = 0;
    std::memcpy(&v, s.data() + at, 8);
    return v;
}

// A record head: end offset, property count, property bytes, name.
std::string record(std::uint64_t end, std::uint64_t count, std::uint64_t bytes,
                   const std::string& name) {
    std::string r;
    putU64(r, end);
    putU64(r, count);
    putU64(r, bytes);
    r.push_back(static_cast<char>(name.size()));
    return r + name;
}

std::string stringProp(const std::string& s) {
    std::string p(1, 'S');
    const auto n = static_cast<std::uint32_t>(s.size());
    p.append(reinterpret_cast<const char*>(&n), 4);
    return p + s;
}

// Walks a binary FBX the way Blender's reader does and fails on anything it would refuse:
// every node with children ends in a 25-byte null record right before its end offset.
void expectWellFormed(const std::string& b) {
    std::function<std::size_t(std::size_t, std::size_t)> node = [&](std::size_t at,
                                                                    std::size_t limit) {
        const std::uint64_t end = u64(b, at);
        EXPECT_LE(end, limit) << "record at " << at;
        const std::size_t props = at + 25 + static_cast<unsigned char>(b[at + 24]);
        std::size_t p = props + u64(b, at + 16);
        if (p < end) {
            while (p < end - 25)
                p = node(p, end);
            EXPECT_EQ(b.substr(end - 25, 25), std::string(25, '\0'))
                << "nested null record of the record at " << at;
        }
        return static_cast<std::size_t>(end);
    };
    std::size_t at = 27;
    while (u64(b, at) != 0)
        at = node(at, b.size());
    EXPECT_EQ(b.substr(at, 25), std::string(25, '\0'));
    const std::string magic("\xf8\x5a\x8c\x6a\xde\xf5\xd9\x7e\xec\xe9\x0c\xe3\x75\x8f\x29\x0b", 16);
    EXPECT_EQ(b.substr(b.size() - 16), magic);
    EXPECT_EQ((b.size() - 16 - 120 - 4) % 16, 0u) << "the version sits on a 16-byte boundary";
}

} // namespace

TEST(FbxFix, AddsNullRecordsAndFooterWithHandComputedOffsets) {
    // Assimp's form: A (offset 27, 26 bytes of head) holds B (offset 53: head 26 + an 'I'
    // property of 5 bytes = 31 bytes, ends at 84); A ends where B ends, with no null record.
    std::string in = header();
    in += record(84, 0, 0, "A");
    in += record(84, 1, 5, "B");
    in += "I";
    const std::int32_t seven = 7;
    in.append(reinterpret_cast<const char*>(&seven), 4);
    in += std::string(25, '\0') + "assimp's footer, replaced";

    const std::string out = exporter::repairAssimpFbxBinary(in);
    // A: 27..53 head, B 53..84, A's null record 84..109; top-level null record 109..134;
    // footer id 134..150, 4 zeros ..154, padding to 160, version 160..164, 120 zeros ..284,
    // magic 284..300.
    ASSERT_EQ(out.size(), 300u);
    EXPECT_EQ(out.substr(0, 27), header());
    EXPECT_EQ(u64(out, 27), 109u);
    EXPECT_EQ(u64(out, 53), 84u);
    EXPECT_EQ(out.substr(53 + 26, 5), in.substr(53 + 26, 5)) << "property bytes unchanged";
    EXPECT_EQ(out.substr(84, 50), std::string(50, '\0'));
    EXPECT_EQ(static_cast<unsigned char>(out[134]), 0xfa);
    std::uint32_t version = 0;
    std::memcpy(&version, out.data() + 160, 4);
    EXPECT_EQ(version, 7500u);
    expectWellFormed(out);
    // A file that is already right comes out byte for byte the same.
    EXPECT_EQ(exporter::repairAssimpFbxBinary(out), out);
}

TEST(FbxFix, StatesMetresInGlobalSettings) {
    std::string props = stringProp("UnitScaleFactor") + stringProp("double") +
                        stringProp("Number") + stringProp("");
    props += "D";
    const double one = 1.0;
    props.append(reinterpret_cast<const char*>(&one), 8);
    // GlobalSettings { Properties70 { P: ... } }, Assimp style (no null records).
    const std::size_t p = 27 + (25 + 14) + (25 + 12), end = p + 26 + props.size();
    std::string in = header();
    in += record(end, 0, 0, "GlobalSettings");
    in += record(end, 0, 0, "Properties70");
    in += record(end, 5, props.size(), "P") + props;
    in += std::string(25, '\0');
    const std::string out = exporter::repairAssimpFbxBinary(in, 100.0);
    double unit = 0;
    std::memcpy(&unit, out.data() + p + 26 + props.size() - 8, 8);
    EXPECT_EQ(unit, 100.0);
    expectWellFormed(out);

    const std::string ascii =
        "\t\tP: \"UnitScaleFactor\", \"double\", \"Number\", \"\",1\n"
        "\t\tP: \"OriginalUnitScaleFactor\", \"double\", \"Number\", \"\", 1\n";
    EXPECT_EQ(exporter::setFbxAsciiUnitScale(ascii, 100.0),
              "\t\tP: \"UnitScaleFactor\", \"double\", \"Number\", \"\",100\n"
              "\t\tP: \"OriginalUnitScaleFactor\", \"double\", \"Number\", \"\", 100\n");
}

TEST(FbxFix, RefusesMalformedInput) {
    EXPECT_THROW(exporter::repairAssimpFbxBinary("not an fbx"), InvalidInput);
    EXPECT_THROW(exporter::repairAssimpFbxBinary(header(7400) + std::string(25, '\0')),
                 InvalidInput);
    std::string in = header();
    in += record(84, 0, 0, "A");
    in += record(84, 1, 5, "B");
    EXPECT_THROW(exporter::repairAssimpFbxBinary(in), InvalidInput) << "truncated";
    std::string wild = header();
    wild += record(1u << 30, 0, 0, "A") + std::string(25, '\0');
    EXPECT_THROW(exporter::repairAssimpFbxBinary(wild), InvalidInput) << "end past the file";
}

TEST(FbxFix, RealExportIsWellFormed) {
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    m.uvs = {{0, 0}, {1, 0}, {0, 1}};
    m.indices = {0, 1, 2};
    m.submeshes = {{"bark", 0, 3}};
    exporter::SceneDesc scene;
    scene.meshes = {{"tri", &m}};
    scene.instances = {{"tri_0", 0, {0, 0, 0}}, {"tri_1", 0, {5, 0, 0}}};
    const auto dir = std::filesystem::temp_directory_path() / "sylva_fbxfix";
    std::filesystem::create_directories(dir);
    exporter::writeScene(dir / "t.fbx", scene, exporter::SceneFormat::Fbx);
    std::ifstream in(dir / "t.fbx", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 300u);
    expectWellFormed(bytes);
    std::filesystem::remove_all(dir);
}
