#include "cairn/systems/primitives/gain.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::systems {
namespace {

int CheckedSize(int size) {
  if (size <= 0) throw std::invalid_argument("Gain: size must be positive; got " + std::to_string(size) + ".");
  return size;
}

}  // namespace

Gain::Gain(double k, int size) : Gain(Eigen::VectorXd::Constant(CheckedSize(size), k)) {}

Gain::Gain(const Eigen::VectorXd& k) : k_(k) {
  const int size = static_cast<int>(k.size());
  if (size < 1) throw std::invalid_argument("Gain: the gain vector must not be empty.");
  for (int i = 0; i < size; ++i) {
    if (!std::isfinite(k[i])) {
      throw std::invalid_argument("Gain: gain element " + std::to_string(i) + " is " + FormatShort(k[i]) +
                                  "; gains must be finite.");
    }
  }
  const auto& u = DeclareVectorInputPort("u", size);
  DeclareVectorOutputPort("y", size, &Gain::CalcOutput, {u.ticket()});
}

void Gain::CalcOutput(const Context& context, Eigen::VectorXd* y) const {
  *y = k_.cwiseProduct(get_input_port().Eval<Eigen::VectorXd>(context));
}

}  // namespace cairn::systems
