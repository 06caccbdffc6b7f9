#include "document/scenebuild.h"

#include "document/speciesfile.h"
#include "engine/mesh/season.h"
#include "engine/nodes/adaptnode.h"
#include "engine/util/error.h"

#include <QFileInfo>

#include <cmath>
#include <optional>

namespace sylva::doc {

std::vector<env::ObstacleSpec> obstacleSpecsOf(const Project& project) {
    std::vector<env::ObstacleSpec> obstacles;
    for (const ProjectObstacle& o : project.obstacles) {
        env::ObstacleSpec spec;
        spec.file = project.resolve(o.file).toStdString();
        spec.transform.translate = o.translate;
        spec.transform.rotateDeg = o.rotate;
        spec.transform.scale = o.scale;
        obstacles.push_back(spec);
    }
    return obstacles;
}

env::ObstacleSpec terrainSpecOf(const Project& project, const PlacementDomain& d) {
    env::ObstacleSpec spec;
    spec.file = project.resolve(d.terrain).toStdString();
    return spec;
}

forest::ForestScene makeForestScene(const Project& original) {
    // Ids name the trees: a project built in memory without them gets the ones saving would give.
    std::optional<Project> withIds;
    bool missing = false;
    for (const ProjectInstance& t : original.instances)
        missing = missing || t.id == 0;
    for (const PlacementDomain& d : original.domains)
        missing = missing || d.id == 0;
    if (missing) {
        withIds = original;
        assignIds(*withIds);
    }
    const Project& project = withIds ? *withIds : original;
    forest::ForestScene s;
    s.seed = project.seed;
    s.camera = project.cameraPosition;
    s.lightDirection = project.lightDirection;
    if (!project.season.empty()) s.season = mesh::parseSeason(project.season);

    std::map<std::string, std::uint32_t> speciesIndex;
    for (const ProjectSpecies& ps : project.species) {
        forest::SceneSpecies species;
        species.name = ps.name;
        species.variants = ps.variants;
        if (ps.graph) {
            species.graph = speciesFromGraph(ps.name, *ps.graph, ps.traits, project.baseDir);
        } else {
            species.graph = loadSpecies(project.resolve(ps.file));
        }
        speciesIndex[ps.name] = static_cast<std::uint32_t>(s.species.size());
        s.species.push_back(std::move(species));
    }

    if (const auto obstacles = obstacleSpecsOf(project); !obstacles.empty())
        s.obstacles = env::loadObstacleScene(obstacles);

    for (const PlacementDomain& d : project.domains) {
        placement::Domain domain;
        domain.id = d.id;
        if (d.shape == "polygon") {
            domain.shape = placement::DomainShape::Polygon;
            domain.polygon = d.polygon;
        } else if (d.shape == "terrain") {
            // Trees go where a ray down meets the terrain, within the terrain's footprint.
            s.ground = env::loadObstacleScene({terrainSpecOf(project, d)});
            domain.min = {s.ground->lo().x, s.ground->lo().z};
            domain.max = {s.ground->hi().x, s.ground->hi().z};
        } else {
            domain.min = d.min;
            domain.max = d.max;
        }
        for (const auto& [name, count] : d.counts)
            domain.counts.emplace_back(name, static_cast<std::size_t>(count));
        s.domains.push_back(std::move(domain));
    }

    for (const ProjectInstance& pi : project.instances) {
        placement::Instance in;
        in.id = pi.id;
        in.species = speciesIndex.at(pi.species);
        in.position = pi.position;
        const double turns = pi.rotation / 360.0 - std::floor(pi.rotation / 360.0); // [0, 1)
        in.rotation = static_cast<float>(turns * 2.0 * M_PI);
        in.scale = static_cast<float>(pi.scale);
        in.growth = static_cast<float>(pi.growth);
        in.seed = pi.seed;
        in.handPlaced = true;
        if (!pi.season.empty()) in.season = static_cast<std::int8_t>(mesh::parseSeason(pi.season));
        s.handPlaced.push_back(in);
        if (!pi.branchEdits.empty()) s.branchEdits[pi.id] = pi.branchEdits;
    }
    return s;
}

} // namespace sylva::doc
