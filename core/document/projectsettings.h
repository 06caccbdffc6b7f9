#pragma once

#include <string>
#include <vector>

#include <QString>

namespace sylva::doc {

/// One setting of a project as every front door shows it (issue 42: "one spec for project
/// settings"), the shape of the engine's ParamSpec: the file's key, a label and help for people,
/// the unit, the allowed range and the default, the step and decimals an editor offers. The
/// parser, the document's setters, the Properties panel, Python's docstrings and the CLI's usage
/// read it; ranges that the engine checks too come from the engine's one statement of them
/// (wind::kStrengthRange ...). Labels and help are untranslated English (QT_TRANSLATE_NOOP in
/// the context "sylva::doc::ProjectSettings"): the editor translates them with label()/help().
struct SettingSpec {
    const char* key;   ///< "wind.strength": the file's object and key
    const char* label; ///< "Wind strength"
    const char* unit;  ///< "", "Hz", "°"
    double min = 0.0, max = 0.0, defaultValue = 0.0;
    double step = 1.0;
    int decimals = 0;
    const char* help;
    /// The command-line option that overrides it ("--wind-strength"); nullptr where none does
    /// (the wind's direction is given as a vector there, not in degrees).
    const char* cliOption = nullptr;

    /// InvalidInput "<key> must be in [min, max], got <value>" unless min <= value <= max.
    void check(double value) const;
    /// "0 .. 2", "0.05 .. 5 Hz": the range as the CLI's usage and Python's docstrings say it.
    std::string rangeText() const;
    /// The label and help translated (the editor's language).
    QString translatedLabel() const;
    QString translatedHelp() const;
};

namespace settings {
/// The wind's direction about the vertical (the file holds the vector; people see degrees).
extern const SettingSpec kWindDirection;
extern const SettingSpec kWindStrength;
extern const SettingSpec kWindGustiness;
extern const SettingSpec kWindFrequency;
/// A species' K: how many variants its instanced trees share ("variants" of a species entry).
extern const SettingSpec kVariants;
} // namespace settings

/// The names DocumentChange::settings uses: what a settings edit changed.
namespace settingChange {
inline constexpr const char* kSeed = "seed";
inline constexpr const char* kCamera = "camera";
inline constexpr const char* kLight = "light";
inline constexpr const char* kSeason = "season";
inline constexpr const char* kWind = "wind";
} // namespace settingChange

} // namespace sylva::doc
