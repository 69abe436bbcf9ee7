#include "cairn/perception/friction/material_registry.h"

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "cairn/common/number_text.h"
#include "cairn/common/atomic_file.h"
#include "cairn/common/internal/yaml_reader.h"
#include "cairn/common/text_suggestions.h"

namespace cairn::perception {
namespace {

using cairn::internal::YamlReader;

// Bounds on what a registry file may state.
constexpr int kMaxMaterials = 1000;
constexpr long long kMaxContacts = 1000000000;

// The posterior of μ ~ N(m, s²) after one observation, and the observation's likelihood under N(m, s²).
struct Posterior {
  double mean;
  double variance;
  double likelihood;
};

Posterior UpdateNormal(double m, double s, const ContactObservation& observation) {
  const double s2 = s * s;
  switch (observation.kind) {
    case ContactObservation::Kind::kMeasured: {
      const double r2 = observation.stddev * observation.stddev;
      const double variance = 1.0 / (1.0 / s2 + 1.0 / r2);
      const double mean = variance * (m / s2 + observation.value / r2);
      const double total = s2 + r2;
      const double z = observation.value - m;
      return {mean, variance, std::exp(-0.5 * z * z / total) / std::sqrt(2.0 * M_PI * total)};
    }
    case ContactObservation::Kind::kSlipped:
    case ContactObservation::Kind::kHeld: {
      // Truncated-normal moments (μ < r or μ >= r) with the inverse Mills ratio.
      const double alpha = (observation.value - m) / s;
      const double phi = std::exp(-0.5 * alpha * alpha) / std::sqrt(2.0 * M_PI);
      const bool below = observation.kind == ContactObservation::Kind::kSlipped;
      const double mass = below ? StandardNormalCdf(alpha) : 1.0 - StandardNormalCdf(alpha);
      if (mass < 1e-300) return {m, s2, 0.0};
      const double lambda = (below ? -phi : phi) / mass;
      const double mean = m + s * lambda;
      const double variance = s2 * (1.0 + alpha * lambda - lambda * lambda);
      return {mean, variance, mass};
    }
  }
  return {m, s2, 0.0};
}

}  // namespace

MaterialRegistry::MaterialRegistry(std::vector<Material> materials) : materials_(std::move(materials)) {
  std::set<std::string> seen;
  for (const Material& material : materials_) {
    if (material.label.empty()) throw std::invalid_argument("MaterialRegistry: a material has an empty label.");
    if (!seen.insert(material.label).second) {
      throw std::invalid_argument("MaterialRegistry: the label '" + material.label +
                                  "' appears twice; labels must be unique.");
    }
  }
}

MaterialRegistry MaterialRegistry::ThesisTable33() {
  std::vector<Material> materials;
  const std::pair<const char*, std::pair<double, double>> measured[] = {
      {"asphalt", {0.74, 0.12}}, {"grass", {0.53, 0.10}}, {"rock", {0.80, 0.08}},  {"carpet", {0.82, 0.02}},
      {"ceramic", {0.97, 0.05}}, {"marble", {0.83, 0.15}}, {"metal", {0.80, 0.15}}, {"wood", {0.88, 0.12}},
  };
  for (const auto& [label, parameters] : measured) {
    materials.push_back({label, FrictionDistribution::Normal(parameters.first, parameters.second), 0});
  }
  for (const char* label : {"sand", "sky", "snow", "water", "cloth", "paper"}) {
    materials.push_back({label, FrictionDistribution::NotWalkable(), 0});
  }
  return MaterialRegistry(std::move(materials));
}

const MaterialRegistry::Material& MaterialRegistry::material(int index) const {
  if (index < 0 || index >= size()) {
    throw std::out_of_range("MaterialRegistry has " + cairn::FormatShort(size()) + " materials; index " +
                            cairn::FormatShort(index) + " is out of range.");
  }
  return materials_[index];
}

std::vector<std::string> MaterialRegistry::labels() const {
  std::vector<std::string> result;
  for (const Material& material : materials_) result.push_back(material.label);
  return result;
}

int MaterialRegistry::IndexOf(const std::string& label) const {
  for (int i = 0; i < size(); ++i) {
    if (materials_[i].label == label) return i;
  }
  throw std::invalid_argument("Unknown material '" + label + "'; did you mean " +
                              QuotedList(ClosestNames(label, labels())) + "?");
}

void MaterialRegistry::ValidateProbabilities(const Eigen::Ref<const Eigen::VectorXd>& probabilities) const {
  if (probabilities.size() != size()) {
    throw std::invalid_argument("Material probabilities have " + cairn::FormatShort(probabilities.size()) +
                                " entries but the registry has " + cairn::FormatShort(size()) +
                                " labels; give one probability per label, in registry order.");
  }
  double sum = 0.0;
  for (int i = 0; i < size(); ++i) {
    const double p = probabilities[i];
    if (!(p >= 0.0 && p <= 1.0)) {
      throw std::invalid_argument("The probability of '" + materials_[i].label + "' is " + FormatShort(p) +
                                  "; probabilities must be in [0, 1].");
    }
    sum += p;
  }
  if (std::abs(sum - 1.0) > 1e-6) {
    throw std::invalid_argument("Material probabilities sum to " + FormatExact(sum) +
                                ", not 1; normalise them (e.g. apply a softmax to the segmenter's scores).");
  }
}

Eigen::VectorXd MaterialRegistry::UpdateFromContact(const Eigen::Ref<const Eigen::VectorXd>& probabilities,
                                                    const ContactObservation& observation) {
  ValidateProbabilities(probabilities);
  if (!(observation.value >= 0.0 && observation.value <= kMaxFrictionCoefficient) ||
      (observation.kind == ContactObservation::Kind::kMeasured &&
       !(observation.stddev > 0.0 && observation.stddev <= kMaxFrictionCoefficient))) {
    throw std::invalid_argument("UpdateFromContact: the observation needs a value in [0, " +
                                FormatShort(kMaxFrictionCoefficient) + "] (got " + FormatShort(observation.value) +
                                ") and, when measured, a noise stddev in (0, " +
                                FormatShort(kMaxFrictionCoefficient) + "] (got " + FormatShort(observation.stddev) +
                                ").");
  }
  const int n = size();
  std::vector<Posterior> posteriors(n, Posterior{0.0, 0.0, 0.0});
  Eigen::VectorXd responsibility = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) {
    if (probabilities[i] == 0.0) continue;
    const FrictionDistribution& prior = materials_[i].friction;
    double likelihood = 0.0;
    if (prior.kind() == FrictionDistribution::Kind::kNotWalkable) {
      // All mass at 0: only "slipped at r > 0" and a measurement near 0 are explained.
      if (observation.kind == ContactObservation::Kind::kSlipped) likelihood = observation.value > 0.0 ? 1.0 : 0.0;
      if (observation.kind == ContactObservation::Kind::kMeasured) {
        const double z = observation.value / observation.stddev;
        likelihood = std::exp(-0.5 * z * z) / (std::sqrt(2.0 * M_PI) * observation.stddev);
      }
    } else if (prior.kind() == FrictionDistribution::Kind::kNormal && prior.b() > 0.0) {
      posteriors[i] = UpdateNormal(prior.a(), prior.b(), observation);
      likelihood = posteriors[i].likelihood;
    } else {
      throw std::invalid_argument("UpdateFromContact: material '" + materials_[i].label + "' has a " +
                                  prior.kind_name() +
                                  " distribution; learning from contact needs normal distributions with a spread > 0.");
    }
    responsibility[i] = probabilities[i] * likelihood;
  }
  const double evidence = responsibility.sum();
  if (!(evidence > 0.0)) {
    throw std::invalid_argument("UpdateFromContact: no material with nonzero probability can explain the observation "
                                "(value " + FormatShort(observation.value) +
                                "); check the probabilities at the contact.");
  }
  responsibility /= evidence;
  for (int i = 0; i < n; ++i) {
    Material& material = materials_[i];
    const double w = responsibility[i];
    if (w == 0.0 || material.friction.kind() != FrictionDistribution::Kind::kNormal) continue;
    // Mixture of "this surface was label i" (posterior) and "it was not" (prior), moment-matched to a normal.
    const double m0 = material.friction.a();
    const double v0 = material.friction.b() * material.friction.b();
    const Posterior& post = posteriors[i];
    const double mean = w * post.mean + (1.0 - w) * m0;
    const double second = w * (post.variance + post.mean * post.mean) + (1.0 - w) * (v0 + m0 * m0);
    material.friction = FrictionDistribution::Normal(mean, std::sqrt(std::max(second - mean * mean, 1e-12)));
    ++material.num_contacts;
  }
  return responsibility;
}

void MaterialRegistry::SaveYaml(const std::string& path) const {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "materials" << YAML::Value << YAML::BeginSeq;
  for (const Material& material : materials_) {
    const FrictionDistribution& f = material.friction;
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "label" << YAML::Value << material.label;
    out << YAML::Key << "distribution" << YAML::Value << f.kind_name();
    if (f.kind() == FrictionDistribution::Kind::kNormal || f.kind() == FrictionDistribution::Kind::kTruncatedNormal) {
      out << YAML::Key << "mean" << YAML::Value << FormatExact(f.a()) << YAML::Key << "stddev" << YAML::Value
          << FormatExact(f.b());
    } else if (f.kind() == FrictionDistribution::Kind::kGeneralizedExtremeValue) {
      out << YAML::Key << "location" << YAML::Value << FormatExact(f.a()) << YAML::Key << "scale" << YAML::Value
          << FormatExact(f.b()) << YAML::Key << "shape" << YAML::Value << FormatExact(f.c());
    }
    if (material.num_contacts > 0) out << YAML::Key << "contacts" << YAML::Value << material.num_contacts;
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  WriteFileAtomically(path, std::string(out.c_str()) + "\n");
}

MaterialRegistry MaterialRegistry::LoadYaml(const std::string& path) {
  const YamlReader yaml(path);
  const YAML::Node& root = yaml.root();
  yaml.CheckKeys(root, {"materials"}, "the material registry");
  const YAML::Node list = yaml.Require(root, "materials", "the material registry");
  if (!list.IsSequence()) yaml.Fail(list, "'materials' must be a list of materials.");
  if (list.size() > static_cast<std::size_t>(kMaxMaterials)) {
    yaml.Fail(list, "'materials' lists " + cairn::FormatShort(list.size()) + " materials; a registry holds at most " +
                        cairn::FormatShort(kMaxMaterials) + ".");
  }
  std::vector<Material> materials;
  for (const YAML::Node& entry : list) {
    if (!YamlReader::Has(entry, "label")) yaml.Fail(entry, "each material needs a 'label'.");
    const std::string label = yaml.String(entry, "label", "a material");
    const std::string where = "material '" + label + "'";
    yaml.CheckKeys(entry, {"label", "distribution", "mean", "stddev", "location", "scale", "shape", "contacts"}, where);
    const std::string kind = yaml.String(entry, "distribution", where, "normal");
    try {
      Material material{label, FrictionDistribution::NotWalkable(), 0};
      if (kind == "normal") {
        material.friction =
            FrictionDistribution::Normal(yaml.Number(entry, "mean", where), yaml.Number(entry, "stddev", where));
      } else if (kind == "truncated_normal") {
        material.friction = FrictionDistribution::TruncatedNormal(yaml.Number(entry, "mean", where),
                                                                  yaml.Number(entry, "stddev", where));
      } else if (kind == "gev") {
        material.friction = FrictionDistribution::GeneralizedExtremeValue(yaml.Number(entry, "location", where),
                                                                          yaml.Number(entry, "scale", where),
                                                                          yaml.Number(entry, "shape", where));
      } else if (kind != "not_walkable") {
        yaml.Fail(entry["distribution"], "unknown distribution '" + kind + "' for " + where +
                                             "; use normal, truncated_normal, gev or not_walkable.");
      }
      CheckPhysicalFriction(material.friction);
      material.num_contacts = static_cast<int>(yaml.Integer(entry, "contacts", where, 0, kMaxContacts, 0));
      materials.push_back(std::move(material));
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      if (message.rfind("In '", 0) == 0) throw;
      throw yaml.Error(entry, where + ": " + message);
    }
  }
  try {
    return MaterialRegistry(std::move(materials));
  } catch (const std::invalid_argument& error) {
    throw yaml.Error(list, error.what());
  }
}

}  // namespace cairn::perception
