#include "scene/wind_reader.hpp"

#include <cstdint>

#include "forces/wind_profile.hpp"

namespace yardsim::scene {

namespace {

using spec::Reader;

// ({spectrum, seed, components, f_min, f_max, height, start, ramp}) => the gusts, or nothing with
// every problem reported at its node (forces/wind_gusts.hpp)
std::optional<forces::GustProperties> gusts(const Reader& r, const YAML::Node& n,
                                            const YAML::Node& wind,
                                            const forces::WindProperties& w) {
  if (!r.keys(n, {"spectrum", "seed", "components", "f_min", "f_max", "height", "start", "ramp"},
              "gusts"))
    return std::nullopt;
  forces::GustProperties g;
  bool ok = r.required(n, "spectrum", "gusts", "the gust spectrum: npd");
  if (const YAML::Node kind = n["spectrum"]) {
    try {
      g.spectrum = forces::gustSpectrumKind(kind.IsScalar() ? kind.Scalar() : "");
    } catch (const std::invalid_argument& e) {
      r.fail(kind, "gusts.spectrum",
             std::string(e.what()) + " " +
                 models::didYouMean(kind.IsScalar() ? kind.Scalar() : "", {"npd"}));
      ok = false;
    }
  }
  g.seed =
      static_cast<std::uint64_t>(spec::wholeNumber(r, n["seed"], "gusts.seed", 1, 0, 2147483647));
  g.components =
      static_cast<int>(spec::wholeNumber(r, n["components"], "gusts.components", 200, 1, 100000));
  g.fMin = r.number(n["f_min"], "gusts.f_min", g.fMin);
  g.fMax = r.number(n["f_max"], "gusts.f_max", g.fMax);
  g.height = r.number(n["height"], "gusts.height", w.referenceHeight);
  g.start = r.number(n["start"], "gusts.start", 0.0);
  g.ramp = r.number(n["ramp"], "gusts.ramp", 0.0);
  // (each value at its own node) => what was expected
  auto check = [&](const char* key, bool good, const std::string& expected) {
    if (good) return;
    r.fail(n[key] ? n[key] : n, std::string("gusts.") + key, expected);
    ok = false;
  };
  check("f_min", g.fMin > 0, "expected a frequency > 0 Hz (the band's lowest; default 1/3600)");
  check("f_max", g.fMax > g.fMin,
        "expected a frequency above f_min = " + std::to_string(g.fMin) + " Hz");
  check("height", g.height > 0,
        "expected a height > 0 m above the still-water level (where the spectrum is taken)");
  check("ramp", g.ramp >= 0, "expected a ramp time >= 0 s");
  // (the wind they blow in) => the NPD profile's 1-hour mean
  if (w.profile != forces::WindProfileKind::Npd) {
    r.fail(n, "gusts",
           "gusts go with profile: npd (the NPD spectrum takes U0, the 1-hour mean at 10 m); "
           "add `profile: npd` to the wind");
    ok = false;
  }
  if (w.averagingTime != 3600.0) {
    r.fail(wind["averaging_time"], "averaging_time",
           "with gusts the profile gives the 1-hour mean: expected 3600 s or none (a shorter "
           "averaging "
           "time's gust factor would count the gusts twice)");
    ok = false;
  }
  if (!(w.speed > 0)) {
    r.fail(wind["speed"], "speed", "gusts need a 1-hour mean speed > 0 m/s");
    ok = false;
  }
  if (!ok) return std::nullopt;
  return g;
}

}  // namespace

void readWind(const Reader& r, const YAML::Node& n, mechanics::MechanicsSpec& spec) {
  if (!r.keys(n,
              {"speed", "direction", "direction_deg", "reference_height", "profile", "exponent",
               "averaging_time", "air_density", "min_height", "gusts"},
              ""))
    return;
  forces::WindProperties w;
  w.speed = r.number(n["speed"], "speed", 0.0, true);
  w.direction = spec::angle(r, n, "", "direction");
  w.referenceHeight = r.number(n["reference_height"], "reference_height", w.referenceHeight);
  w.exponent = r.number(n["exponent"], "exponent", w.exponent);
  w.averagingTime = r.number(n["averaging_time"], "averaging_time", w.averagingTime);
  w.density = r.number(n["air_density"], "air_density", w.density);
  w.minHeight = r.number(n["min_height"], "min_height", w.minHeight);
  w.level = spec.water.level;
  if (const YAML::Node pr = n["profile"]) {
    try {
      w.profile = forces::windProfileKind(pr.IsScalar() ? pr.Scalar() : "");
    } catch (const std::invalid_argument& e) {
      r.fail(pr, "profile",
             std::string(e.what()) + " " +
                 models::didYouMean(pr.IsScalar() ? pr.Scalar() : "",
                                    {"uniform", "power_law", "npd"}));
      return;
    }
  }
  if (const YAML::Node g = n["gusts"]) {
    w.gusts = gusts(r, g, n, w);
    if (!w.gusts) return;
  }
  try {
    forces::WindField check(w);
    spec.wind = w;
  } catch (const std::invalid_argument& e) {
    r.fail(n, "", e.what());
  }
}

}  // namespace yardsim::scene
