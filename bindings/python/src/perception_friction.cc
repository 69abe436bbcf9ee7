// cairn.perception: friction distributions, material registries, segmenters, friction quantile images and the
// FrictionEstimator system.

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "abstract_values.h"
#include "bindings.h"
#include "cairn/common/number_text.h"
#include "cairn/perception/friction/builtin_material_segmenter.h"
#include "cairn/perception/friction/contact_friction_learner.h"
#include "cairn/perception/friction/contact_observation.h"
#include "cairn/perception/friction/friction_distribution.h"
#include "cairn/perception/friction/friction_estimator.h"
#include "cairn/perception/friction/friction_point_cloud.h"
#include "cairn/perception/friction/friction_quantile.h"
#include "cairn/perception/friction/friction_quantile_image.h"
#include "cairn/perception/friction/make_material_segmenter.h"
#include "cairn/perception/friction/material_features.h"
#include "cairn/perception/friction/material_registry.h"
#include "cairn/perception/friction/material_segmenter.h"
#include "cairn/perception/friction/onnx_material_segmenter.h"
#include "cv_mat_caster.h"
#include "numpy_support.h"

namespace cairn::python {

using namespace cairn::perception;

namespace {

py::tuple DistributionState(const FrictionDistribution& d) {
  return py::make_tuple(static_cast<int>(d.kind()), d.a(), d.b(), d.c());
}

FrictionDistribution DistributionFromState(const py::tuple& t) {
  const auto kind = static_cast<FrictionDistribution::Kind>(t[0].cast<int>());
  const auto a = t[1].cast<double>();
  const auto b = t[2].cast<double>();
  switch (kind) {
    case FrictionDistribution::Kind::kNormal: return FrictionDistribution::Normal(a, b);
    case FrictionDistribution::Kind::kTruncatedNormal: return FrictionDistribution::TruncatedNormal(a, b);
    case FrictionDistribution::Kind::kGeneralizedExtremeValue:
      return FrictionDistribution::GeneralizedExtremeValue(a, b, t[3].cast<double>());
    case FrictionDistribution::Kind::kNotWalkable: return FrictionDistribution::NotWalkable();
  }
  throw std::runtime_error("FrictionDistribution: bad pickle state");
}

std::shared_ptr<MaterialSegmenter> Mutable(std::shared_ptr<const MaterialSegmenter> segmenter) {
  return std::const_pointer_cast<MaterialSegmenter>(std::move(segmenter));
}

// `out` must be a writable, C-contiguous float32 (H, W) array of the probabilities' size: then the C++ code writes
// the quantiles straight into its memory.
cv::Mat OutputImage(const py::array& out, const cv::Mat& probabilities) {
  if (!py::isinstance<py::array_t<float>>(out) || out.ndim() != 2 || out.shape(0) != probabilities.rows ||
      out.shape(1) != probabilities.cols || !(out.flags() & py::array::c_style) || !out.writeable()) {
    throw py::value_error("FrictionQuantileImage.Compute: `out` must be a writable C-contiguous float32 array of "
                          "shape (" + cairn::FormatShort(probabilities.rows) + ", " + cairn::FormatShort(probabilities.cols) +
                          ")");
  }
  return cv::Mat(probabilities.rows, probabilities.cols, CV_32F, const_cast<void*>(out.data()));
}

}  // namespace

void DefinePerceptionFriction(py::module_ m) {
  m.def("StandardNormalCdf", &StandardNormalCdf, py::arg("x"), "The standard normal CDF.");
  m.def("StandardNormalQuantile", &StandardNormalQuantile, py::arg("p"), "Its inverse, p in (0, 1).");

  py::class_<FrictionDistribution> distribution(m, "FrictionDistribution",
                                                "A material's distribution of the coefficient of friction (picklable).");
  py::enum_<FrictionDistribution::Kind>(distribution, "Kind", "Distribution families.")
      .value("kNormal", FrictionDistribution::Kind::kNormal, "N(mean, stddev^2).")
      .value("kTruncatedNormal", FrictionDistribution::Kind::kTruncatedNormal, "Normal conditioned on mu >= 0.")
      .value("kGeneralizedExtremeValue", FrictionDistribution::Kind::kGeneralizedExtremeValue, "GEV.")
      .value("kNotWalkable", FrictionDistribution::Kind::kNotWalkable, "All mass at mu = 0.");
  distribution.def_static("Normal", &FrictionDistribution::Normal, py::arg("mean"), py::arg("stddev"), "Normal.")
      .def_static("TruncatedNormal", &FrictionDistribution::TruncatedNormal, py::arg("mean"), py::arg("stddev"),
                  "Normal truncated to [0, inf).")
      .def_static("GeneralizedExtremeValue", &FrictionDistribution::GeneralizedExtremeValue, py::arg("location"),
                  py::arg("scale"), py::arg("shape"), "GEV(location, scale, shape).")
      .def_static("NotWalkable", &FrictionDistribution::NotWalkable, "All mass at 0.")
      .def("kind", &FrictionDistribution::kind, "The family.")
      .def("kind_name", &FrictionDistribution::kind_name, "\"normal\", \"truncated_normal\", \"gev\", ...")
      .def("a", &FrictionDistribution::a, "Mean or location.")
      .def("b", &FrictionDistribution::b, "Standard deviation or scale.")
      .def("c", &FrictionDistribution::c, "GEV shape.")
      .def("walkable", &FrictionDistribution::walkable, "False for not-walkable.")
      .def("Cdf", &FrictionDistribution::Cdf, py::arg("mu"), "F(mu).")
      .def("Pdf", &FrictionDistribution::Pdf, py::arg("mu"), "p(mu).")
      .def("Quantile", &FrictionDistribution::Quantile, py::arg("p"), "The p-quantile.")
      .def("Mean", &FrictionDistribution::Mean, "Mean.")
      .def("Variance", &FrictionDistribution::Variance, "Variance.")
      .def(py::pickle(&DistributionState, &DistributionFromState), "Pickles kind and parameters.");

  py::class_<ContactObservation> observation(m, "ContactObservation",
                                             "What a contact taught about the friction under it.");
  py::enum_<ContactObservation::Kind>(observation, "Kind", "Observation kinds.")
      .value("kMeasured", ContactObservation::Kind::kMeasured, "A measured coefficient with noise.")
      .value("kSlipped", ContactObservation::Kind::kSlipped, "Slipped while using `value`: mu < value.")
      .value("kHeld", ContactObservation::Kind::kHeld, "Held while using `value`: mu >= value.");
  observation.def_static("Measured", &ContactObservation::Measured, py::arg("mu"), py::arg("stddev"), "Measured.")
      .def_static("Slipped", &ContactObservation::Slipped, py::arg("required"), "Slipped.")
      .def_static("Held", &ContactObservation::Held, py::arg("required"), "Held.")
      .def_readonly("kind", &ContactObservation::kind, "The kind.")
      .def_readonly("value", &ContactObservation::value, "The coefficient.")
      .def_readonly("stddev", &ContactObservation::stddev, "Noise of a measurement.");

  py::class_<MaterialRegistry> registry(m, "MaterialRegistry",
                                        "Materials a segmenter reports, each with its friction distribution, in channel "
                                        "order (picklable).");
  py::class_<MaterialRegistry::Material>(registry, "Material", "One material.")
      .def(py::init([](std::string label, FrictionDistribution friction, int num_contacts) {
             return MaterialRegistry::Material{std::move(label), friction, num_contacts};
           }),
           py::arg("label"), py::arg("friction"), py::arg("num_contacts") = 0, "A material.")
      .def_readonly("label", &MaterialRegistry::Material::label, "Label.")
      .def_readonly("friction", &MaterialRegistry::Material::friction, "Friction distribution.")
      .def_readonly("num_contacts", &MaterialRegistry::Material::num_contacts, "Contacts that updated it.");
  registry.def(py::init<>(), "Empty.")
      .def(py::init<std::vector<MaterialRegistry::Material>>(), py::arg("materials"),
           "ValueError on an empty or duplicate label.")
      .def_static("ThesisTable33", &MaterialRegistry::ThesisTable33, "The thesis' Table 3.3 (14 labels).")
      .def_static("LoadYaml", &MaterialRegistry::LoadYaml, py::arg("path"), "Reads a registry from YAML.")
      .def("SaveYaml", &MaterialRegistry::SaveYaml, py::arg("path"), "Writes the registry atomically.")
      .def("size", &MaterialRegistry::size, "Number of materials.")
      .def("material", &MaterialRegistry::material, py::arg("index"), "Material `index`.")
      .def("materials", &MaterialRegistry::materials, "Every material.")
      .def("IndexOf", &MaterialRegistry::IndexOf, py::arg("label"), "Index of a label; ValueError with closest.")
      .def("labels", &MaterialRegistry::labels, "Labels in order.")
      .def("ValidateProbabilities", &MaterialRegistry::ValidateProbabilities, py::arg("probabilities"),
           "ValueError unless one probability per label, in [0, 1], summing to 1.")
      .def("UpdateFromContact", &MaterialRegistry::UpdateFromContact, py::arg("probabilities"), py::arg("observation"),
           "Learns from one contact; returns the posterior label probabilities.")
      .def(py::pickle(
               [](const MaterialRegistry& r) {
                 py::list materials;
                 for (const auto& material : r.materials()) {
                   materials.append(py::make_tuple(material.label, DistributionState(material.friction),
                                                   material.num_contacts));
                 }
                 return py::make_tuple(materials);
               },
               [](const py::tuple& t) {
                 std::vector<MaterialRegistry::Material> materials;
                 for (py::handle item : t[0].cast<py::list>()) {
                   const auto entry = item.cast<py::tuple>();
                   materials.push_back({entry[0].cast<std::string>(), DistributionFromState(entry[1].cast<py::tuple>()),
                                        entry[2].cast<int>()});
                 }
                 return MaterialRegistry(std::move(materials));
               }),
           "Pickles every material.");

  py::enum_<QuantileMethod>(m, "QuantileMethod", "How to find a mixture's friction quantile.")
      .value("kSearch", QuantileMethod::kSearch, "The thesis' Algorithm 1 (uniform search).")
      .value("kExact", QuantileMethod::kExact, "Bisection to the tolerance.")
      .value("kGaussian", QuantileMethod::kGaussian, "Moment-matched Gaussian.");
  m.def("MixtureCdf", &MixtureCdf, py::arg("registry"), py::arg("probabilities"), py::arg("mu"),
        "The per-pixel mixture CDF F(mu).");
  m.def("FrictionQuantile", &FrictionQuantile, py::arg("registry"), py::arg("probabilities"), py::arg("eta"),
        py::arg("method"), py::arg("tolerance") = 1e-4, "The lower friction bound Q_{1-eta} of one pixel.");
  m.def("FrictionQuantiles", &FrictionQuantiles, py::arg("registry"), py::arg("probabilities"), py::arg("eta"),
        py::arg("method"), py::arg("tolerance") = 1e-4, "Q_{1-eta} for every row of a pixels x labels matrix.");

  py::class_<FrictionQuantileImage> quantile_image(m, "FrictionQuantileImage",
                                                   "Friction quantile images from per-pixel material probabilities, "
                                                   "at frame rate (tabulated CDFs).");
  py::class_<FrictionQuantileImage::Options>(quantile_image, "Options", "Settings.")
      .def(py::init<>(), "eta 0.95, exact method.")
      .def_readwrite("eta", &FrictionQuantileImage::Options::eta, "Confidence eta.")
      .def_readwrite("method", &FrictionQuantileImage::Options::method, "QuantileMethod.")
      .def_readwrite("tolerance", &FrictionQuantileImage::Options::tolerance, "Step of kSearch.")
      .def_readwrite("num_threads", &FrictionQuantileImage::Options::num_threads, "Threads (0: one per core).");
  quantile_image
      .def(py::init<const MaterialRegistry&, const FrictionQuantileImage::Options&>(), py::arg("registry"),
           py::arg("options") = FrictionQuantileImage::Options(), "ValueError for bad options or an empty registry.")
      .def(
          "Compute",
          [](const FrictionQuantileImage& self, const cv::Mat& probabilities) {
            cv::Mat quantiles;
            py::gil_scoped_release release;
            self.Compute(probabilities, &quantiles);
            return quantiles;
          },
          py::arg("probabilities"),
          "Q_{1-eta} per pixel (float32 H x W) of an H x W x labels float32 probability array (read without a "
          "copy); ValueError naming the first bad pixel.")
      .def(
          "Compute",
          [](const FrictionQuantileImage& self, const cv::Mat& probabilities, py::array out) {
            cv::Mat quantiles = OutputImage(out, probabilities);
            const void* expected = quantiles.data;
            {
              py::gil_scoped_release release;
              self.Compute(probabilities, &quantiles);
            }
            if (quantiles.data != expected) throw std::logic_error("FrictionQuantileImage.Compute: output moved");
            return out;
          },
          py::arg("probabilities"), py::arg("out"),
          "As Compute(probabilities), writing into `out` (a preallocated float32 (H, W) array, written in place "
          "without a copy); returns `out`.")
      .def("options", &FrictionQuantileImage::options, "The options.")
      .def("num_labels", &FrictionQuantileImage::num_labels, "Number of labels.")
      .def("cdf_interpolation_error", &FrictionQuantileImage::cdf_interpolation_error,
           "Largest tabulated CDF error of kExact.");

  py::class_<MaterialFeatures>(m, "MaterialFeatures", "Per-patch colour and texture descriptors (20 values).")
      .def(py::init<int, int>(), py::arg("window") = 15, py::arg("stride") = 8, "ValueError for bad sizes.")
      .def(
          "GridSize",
          [](const MaterialFeatures& self, int width, int height) {
            const cv::Size size = self.GridSize(cv::Size(width, height));
            return py::make_tuple(size.width, size.height);
          },
          py::arg("width"), py::arg("height"), "(columns, rows) of the patch grid of an image.")
      .def("CentreOf", &MaterialFeatures::CentreOf, py::arg("i"), py::arg("extent"), "Pixel of grid index i.")
      .def("Compute", &MaterialFeatures::Compute, py::arg("image"), py::call_guard<py::gil_scoped_release>(),
           "Descriptors of every patch: float32 (patches, 20).")
      .def("window", &MaterialFeatures::window, "Patch side.")
      .def("stride", &MaterialFeatures::stride, "Grid stride.")
      .attr("kDimension") = MaterialFeatures::kDimension;

  py::class_<MaterialSegmenter, std::shared_ptr<MaterialSegmenter>>(
      m, "MaterialSegmenter", "Per-pixel material probabilities from an image: the interface of every back-end.")
      .def("labels", &MaterialSegmenter::labels, "Labels in channel order.")
      .def("num_labels", &MaterialSegmenter::num_labels, "Number of labels.")
      .def("Segment", &MaterialSegmenter::Segment, py::arg("image"), py::call_guard<py::gil_scoped_release>(),
           "float32 H x W x labels probabilities of a uint8 grey or BGR image (without the GIL).");

  py::class_<BuiltinMaterialSegmenter, MaterialSegmenter, std::shared_ptr<BuiltinMaterialSegmenter>> builtin(
      m, "BuiltinMaterialSegmenter", "Patch features classified by a small calibrated perceptron.");
  py::class_<BuiltinMaterialSegmenter::TrainingOptions>(builtin, "TrainingOptions", "How Train works.")
      .def(py::init<>(), "Defaults.")
      .def_readwrite("window", &BuiltinMaterialSegmenter::TrainingOptions::window, "Patch side.")
      .def_readwrite("stride", &BuiltinMaterialSegmenter::TrainingOptions::stride, "Grid stride.")
      .def_readwrite("hidden_units", &BuiltinMaterialSegmenter::TrainingOptions::hidden_units, "Hidden units.")
      .def_readwrite("epochs", &BuiltinMaterialSegmenter::TrainingOptions::epochs, "Epochs.")
      .def_readwrite("learning_rate", &BuiltinMaterialSegmenter::TrainingOptions::learning_rate, "Adam step.")
      .def_readwrite("weight_decay", &BuiltinMaterialSegmenter::TrainingOptions::weight_decay, "L2 penalty.")
      .def_readwrite("calibration_fraction", &BuiltinMaterialSegmenter::TrainingOptions::calibration_fraction,
                     "Held-out fraction.")
      .def_readwrite("max_samples_per_label", &BuiltinMaterialSegmenter::TrainingOptions::max_samples_per_label,
                     "Samples per label.")
      .def_readwrite("seed", &BuiltinMaterialSegmenter::TrainingOptions::seed, "Seed.");
  py::class_<BuiltinMaterialSegmenter::TrainingReport>(builtin, "TrainingReport", "What Train measured.")
      .def_readonly("num_training_samples", &BuiltinMaterialSegmenter::TrainingReport::num_training_samples, "Count.")
      .def_readonly("num_calibration_samples", &BuiltinMaterialSegmenter::TrainingReport::num_calibration_samples,
                    "Count.")
      .def_readonly("training_accuracy", &BuiltinMaterialSegmenter::TrainingReport::training_accuracy, "Accuracy.")
      .def_readonly("calibration_accuracy", &BuiltinMaterialSegmenter::TrainingReport::calibration_accuracy,
                    "Accuracy.")
      .def_readonly("temperature", &BuiltinMaterialSegmenter::TrainingReport::temperature, "Temperature.")
      .def_readonly("ece_before", &BuiltinMaterialSegmenter::TrainingReport::ece_before, "ECE at T = 1.")
      .def_readonly("ece_after", &BuiltinMaterialSegmenter::TrainingReport::ece_after, "ECE after scaling.");
  builtin
      .def_static(
          "Train",
          [](const std::vector<std::string>& labels, const std::vector<cv::Mat>& images,
             const std::vector<cv::Mat>& label_images, const BuiltinMaterialSegmenter::TrainingOptions& options) {
            BuiltinMaterialSegmenter::TrainingReport report;
            std::optional<BuiltinMaterialSegmenter> segmenter;
            {
              py::gil_scoped_release release;
              segmenter.emplace(BuiltinMaterialSegmenter::Train(labels, images, label_images, options, &report));
            }
            return py::make_tuple(std::make_shared<BuiltinMaterialSegmenter>(std::move(*segmenter)), report);
          },
          py::arg("labels"), py::arg("images"), py::arg("label_images"),
          py::arg("options") = BuiltinMaterialSegmenter::TrainingOptions(),
          "Trains on uint8 images and uint8 label images (255 = unlabelled); returns (segmenter, report).")
      .def_static(
          "Load", [](const std::string& path) { return std::make_shared<BuiltinMaterialSegmenter>(BuiltinMaterialSegmenter::Load(path)); },
          py::arg("path"), "Reads a model written by Save().")
      .def("Save", &BuiltinMaterialSegmenter::Save, py::arg("path"), "Writes the model as YAML, atomically.")
      .def("SegmentGrid", &BuiltinMaterialSegmenter::SegmentGrid, py::arg("image"),
           py::call_guard<py::gil_scoped_release>(), "Probabilities on the patch grid.")
      .def("features", &BuiltinMaterialSegmenter::features, "The feature extractor.")
      .def("temperature", &BuiltinMaterialSegmenter::temperature, "The fitted temperature.")
      .def("hidden_units", &BuiltinMaterialSegmenter::hidden_units, "Hidden units.");

  py::class_<OnnxMaterialSegmenter, MaterialSegmenter, std::shared_ptr<OnnxMaterialSegmenter>>(
      m, "OnnxMaterialSegmenter", "A segmentation network (ONNX) run by OpenCV dnn.")
      .def_static(
          "Load", [](const std::string& path) { return std::make_shared<OnnxMaterialSegmenter>(OnnxMaterialSegmenter::Load(path)); },
          py::arg("yaml_path"), "Reads the YAML description and the model.")
      .def("model_path", &OnnxMaterialSegmenter::model_path, "The model file.")
      .def("SegmentNative", &OnnxMaterialSegmenter::SegmentNative, py::arg("image"),
           py::call_guard<py::gil_scoped_release>(), "Probabilities at the network's resolution.");

  m.def(
      "MakeMaterialSegmenter",
      [](const std::string& specification) { return Mutable(MakeMaterialSegmenter(specification)); },
      py::arg("specification"), "\"builtin:PATH\" or \"onnx:PATH\".");

  py::class_<FrictionPointCloud>(m, "FrictionPointCloud",
                                 "World points with their friction quantile and material weights.")
      .def(py::init<>(), "Empty.")
      .def(py::init([](const Eigen::MatrixX3d& points, const Eigen::VectorXf& quantiles, const Eigen::MatrixXf& weights) {
             if (quantiles.size() != points.rows() || weights.rows() != points.rows()) {
               throw std::invalid_argument("FrictionPointCloud: " + cairn::FormatShort(points.rows()) + " points, " +
                                           cairn::FormatShort(quantiles.size()) + " quantiles and " +
                                           cairn::FormatShort(weights.rows()) + " weight rows; give one of each per point");
             }
             FrictionPointCloud cloud;
             for (Eigen::Index i = 0; i < points.rows(); ++i) cloud.points_W.emplace_back(points.row(i).transpose());
             cloud.quantiles.assign(quantiles.data(), quantiles.data() + quantiles.size());
             cloud.weights = weights;
             return cloud;
           }),
           py::arg("points_W"), py::arg("quantiles"), py::arg("weights"),
           "From (n, 3) world points, n quantiles and (n, labels) registry-order weights.")
      .def_property_readonly("points_W", [](const FrictionPointCloud& c) { return StackRows(c.points_W); },
                             "(n, 3) points (a copy).")
      .def_property_readonly(
          "quantiles",
          [](const FrictionPointCloud& c) {
            py::array_t<float> out(static_cast<py::ssize_t>(c.quantiles.size()));
            std::copy(c.quantiles.begin(), c.quantiles.end(), out.mutable_data());
            return out;
          },
          "Q_{1-eta} per point (a copy).")
      .def_property_readonly("weights", [](const FrictionPointCloud& c) { return Eigen::MatrixXf(c.weights); },
                             "(n, labels) material weights (a copy).")
      .def("size", &FrictionPointCloud::size, "Number of points.");

  py::class_<FrictionEstimator, systems::LeafSystem> estimator(
      m, "FrictionEstimator",
      "System: input `image` (Image), optional `depth` (float32 Image) and `X_WC` (4x4); outputs "
      "`material_probabilities`, `friction_quantile` (Images) and, with geometry, `friction_points`.");
  py::class_<FrictionEstimator::Options>(estimator, "Options", "Settings.")
      .def(py::init<>(), "eta 0.95, exact, no geometry.")
      .def_readwrite("eta", &FrictionEstimator::Options::eta, "Confidence eta.")
      .def_readwrite("method", &FrictionEstimator::Options::method, "QuantileMethod.")
      .def_readwrite("search_step", &FrictionEstimator::Options::search_step, "Step of kSearch.")
      .def_readwrite("num_threads", &FrictionEstimator::Options::num_threads, "Threads.")
      .def_readwrite("with_geometry", &FrictionEstimator::Options::with_geometry, "Declare depth/pose/points.")
      .def_readwrite("camera", &FrictionEstimator::Options::camera, "Intrinsics for the points.");
  estimator
      .def(py::init([](MaterialRegistry registry, std::shared_ptr<MaterialSegmenter> segmenter,
                       const FrictionEstimator::Options& options) {
             return std::make_unique<FrictionEstimator>(std::move(registry), std::move(segmenter), options);
           }),
           py::arg("registry"), py::arg("segmenter"), py::arg("options") = FrictionEstimator::Options(),
           "ValueError naming a segmenter label the registry lacks.")
      .def("SetEta", &FrictionEstimator::SetEta, py::arg("context"), py::arg("eta"), "Sets eta in `context`.")
      .def("eta_parameter", &FrictionEstimator::eta_parameter, "Index of the numeric parameter eta.")
      .def("registry_parameter", &FrictionEstimator::registry_parameter, "Index of the registry parameter.");

  RegisterBoundAbstractValueType<MaterialRegistry>("MaterialRegistry");

  py::class_<FootContact>(m, "FootContact", "A foot's contact: where, and what it taught about friction there.")
      .def(py::init([](const Eigen::Vector3d& position_W, const ContactObservation& observation) {
             return FootContact{position_W, observation};
           }),
           py::arg("position_W"), py::arg("observation"), "A contact at `position_W` (m) and what it taught.")
      .def_readwrite("position_W", &FootContact::position_W, "Contact point in the world, m.")
      .def_readwrite("observation", &FootContact::observation, "ContactObservation.");
  RegisterConvertedAbstractValueType<std::vector<FootContact>>("FootContacts");
  py::class_<ContactLearning>(m, "ContactLearning", "ContactFrictionLearner's state.")
      .def_readonly("registry", &ContactLearning::registry, "The learned MaterialRegistry.")
      .def_readonly("seen", &ContactLearning::seen, "Contacts of the log read.")
      .def_readonly("learned", &ContactLearning::learned, "Contacts that updated the registry.")
      .def_readonly("skipped", &ContactLearning::skipped, "Contacts with no perceived point under the foot.")
      .def_readonly("rejected", &ContactLearning::rejected, "Contacts the registry refused.");
  py::class_<ContactFrictionLearner, systems::LeafSystem>(
      m, "ContactFrictionLearner",
      "System: inputs `contacts` (list of FootContact, append-only) and `friction_points` (FrictionPointCloud); "
      "output `registry` (MaterialRegistry learned from touch).")
      .def(py::init([](MaterialRegistry registry, double period, double radius, double height_window) {
             return std::make_unique<ContactFrictionLearner>(std::move(registry), period, radius, height_window);
           }),
           py::arg("registry"), py::arg("period"), py::arg("radius") = 0.05, py::arg("height_window") = 0.05,
           "ValueError for an empty registry, a bad period, radius or height window.")
      .def(
          "learning",
          [](const ContactFrictionLearner& self, const systems::Context& context) { return self.learning(context); },
          py::arg("context"), "The state in `context` (a copy).")
      .def(
          "MixtureUnder",
          [](const ContactFrictionLearner& self, const FrictionPointCloud& points,
             const Eigen::Vector3d& position_W) -> py::object {
            Eigen::VectorXd mixture;
            if (!self.MixtureUnder(points, position_W, &mixture)) return py::none();
            return py::cast(mixture);
          },
          py::arg("points"), py::arg("position_W"), "Mean material mixture under a contact point, or None.");
  RegisterBoundAbstractValueType<FrictionPointCloud>("FrictionPointCloud");
}

}  // namespace cairn::python
