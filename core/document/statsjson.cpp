#include "document/statsjson.h"

#include <charconv>

namespace sylva::doc {

void appendJsonNumber(std::string& out, const char* key, double value, bool comma) {
    char buf[32];
    // Counts as integers: the shortest form of 100000.0 is "1e+05", which scripts read as a float.
    const bool integral = value > -9.0e15 && value < 9.0e15 &&
                          value == static_cast<double>(static_cast<long long>(value));
    const auto end = integral
                         ? std::to_chars(buf, buf + sizeof buf, static_cast<long long>(value)).ptr
                         : std::to_chars(buf, buf + sizeof buf, value).ptr;
    out += '"';
    out += key;
    out += "\":";
    out.append(buf, end);
    if (comma) out += ',';
}

std::string metricsJson(const forest::SceneMetrics& m) {
    std::string json = "{";
    appendJsonNumber(json, "trees", static_cast<double>(m.trees));
    appendJsonNumber(json, "mean_height_m", m.meanHeightM);
    appendJsonNumber(json, "mean_dbh_m", m.meanDbhM);
    appendJsonNumber(json, "mean_crown_width_m", m.meanCrownWidthM);
    appendJsonNumber(json, "wood_volume_m3", m.woodVolumeM3);
    appendJsonNumber(json, "dry_biomass_kg", m.dryBiomassKg);
    appendJsonNumber(json, "carbon_kg", m.carbonKg);
    appendJsonNumber(json, "co2_kg", m.co2Kg);
    appendJsonNumber(json, "chave_agb_kg", m.chaveAgbKg, false);
    return json + "}";
}

} // namespace sylva::doc
