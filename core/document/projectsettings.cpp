#include "document/projectsettings.h"

#include <charconv>

#include <QCoreApplication>

#include "document/project.h"
#include "engine/util/error.h"
#include "engine/util/text.h"
#include "engine/wind/windmodel.h"

namespace sylva::doc {

void SettingSpec::check(double value) const {
    requireRange(key, value, min, max);
}

std::string SettingSpec::rangeText() const {
    std::string out = shortestDecimal(min);
    out.append(" .. ");
    out.append(shortestDecimal(max));
    const std::string u(unit);
    if (!u.empty() && u != "°") out.push_back(' ');
    out.append(u);
    return out;
}

QString SettingSpec::translatedLabel() const {
    return QCoreApplication::translate("sylva::doc::ProjectSettings", label);
}

QString SettingSpec::translatedHelp() const {
    return QCoreApplication::translate("sylva::doc::ProjectSettings", help);
}

namespace settings {

const SettingSpec kWindDirection{
    "wind.direction",
    QT_TRANSLATE_NOOP("sylva::doc::ProjectSettings", "Wind direction"),
    "°",
    0.0,
    360.0,
    0.0,
    15.0,
    0,
    QT_TRANSLATE_NOOP("sylva::doc::ProjectSettings",
                      "Where the wind blows to, about the vertical: 0° along +X, 90° along +Z")};
const SettingSpec kWindStrength{
    "wind.strength",
    QT_TRANSLATE_NOOP("sylva::doc::ProjectSettings", "Wind strength"),
    "",
    wind::kStrengthRange.lo,
    wind::kStrengthRange.hi,
    decimalOf(wind::WindSettings{}.strength),
    0.1,
    2,
    QT_TRANSLATE_NOOP("sylva::doc::ProjectSettings",
                      "0 calm, 1 strong, 2 storm: trees bend with its square"),
    "--wind-strength"};
const SettingSpec kWindGustiness{
    "wind.gustiness",
    QT_TRANSLATE_NOOP("sylva::doc::ProjectSettings", "Gustiness"),
    "",
    wind::kGustinessRange.lo,
    wind::kGustinessRange.hi,
    decimalOf(wind::WindSettings{}.gustiness),
    0.05,
    2,
    QT_TRANSLATE_NOOP("sylva::doc::ProjectSettings",
                      "0 a steady wind, 1 gusts that double the pressure"),
    "--wind-gustiness"};
const SettingSpec kWindFrequency{
    "wind.frequency",
    QT_TRANSLATE_NOOP("sylva::doc::ProjectSettings", "Sway frequency"),
    "Hz",
    wind::kFrequencyRange.lo,
    wind::kFrequencyRange.hi,
    decimalOf(wind::WindSettings{}.frequency),
    0.05,
    2,
    QT_TRANSLATE_NOOP("sylva::doc::ProjectSettings",
                      "How often the trunks sway; limbs, branches and leaves go faster"),
    "--wind-frequency"};
const SettingSpec kVariants{
    "species.variants",
    QT_TRANSLATE_NOOP("sylva::doc::ProjectSettings", "Variants"),
    "",
    0.0,
    256.0,
    double(kDefaultVariants),
    1.0,
    0,
    QT_TRANSLATE_NOOP("sylva::doc::ProjectSettings",
                      "How many different trees of this species the forest is made of: a tree "
                      "that touches no obstacle and no neighbour's crown shows one of them, "
                      "turned and scaled; one that does is cut back from one of them. Fewer "
                      "variants generate and export faster; 0 grows every tree for its place.")};

} // namespace settings

} // namespace sylva::doc
