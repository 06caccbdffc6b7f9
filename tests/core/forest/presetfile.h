#pragma once

// Minimal species-file reader for engine-only tests (the Qt-side loader lives in core/document).

#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/graph/graph.h"
#include "engine/util/value.h"

namespace sylva::testing {

inline graph::SpeciesGraph loadPreset(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    const sylva::Value root = sylva::Value::parseJson(text.str(), path.string());
    graph::SpeciesGraph g;
    g.name = root.string("name", path.stem().string());
    g.baseDir = path.parent_path();
    g.sourceFile = path.string();
    const sylva::Value& graph = *root.find("graph");
    for (const sylva::Value& n : graph.find("nodes")->toArray()) {
        graph::NodeDesc d;
        d.id = n.string("id", "");
        d.type = n.string("type", "");
        if (const sylva::Value* p = n.find("params")) d.params = *p;
        if (const sylva::Value* ins = n.find("inputs"))
            for (const sylva::Value& i : ins->toArray())
                d.inputs.push_back(i.toString());
        g.nodes.push_back(std::move(d));
    }
    g.output = graph.string("output", g.nodes.back().id);
    if (const sylva::Value* traits = root.find("traits"))
        g.traits.crownRadius = traits->number("crown_radius", 0.0);
    return g;
}

} // namespace sylva::testing
