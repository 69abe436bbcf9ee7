#include "cairn/common/number_text.h"
#include "cairn/systems/primitives/adder.h"

#include <stdexcept>
#include <string>

namespace cairn::systems {

Adder::Adder(int num_inputs, int size) {
  if (num_inputs < 1) {
    throw std::invalid_argument("Adder: needs at least one input; got num_inputs = " + cairn::FormatShort(num_inputs) +
                                ".");
  }
  if (size < 1) throw std::invalid_argument("Adder: size must be positive; got " + cairn::FormatShort(size) + ".");
  for (int i = 0; i < num_inputs; ++i) DeclareVectorInputPort("u" + cairn::FormatShort(i), size);
  DeclareVectorOutputPort("sum", size, &Adder::CalcSum, {all_input_ports_ticket()});
}

void Adder::CalcSum(const Context& context, Eigen::VectorXd* sum) const {
  sum->setZero();
  for (int i = 0; i < num_input_ports(); ++i) *sum += get_input_port(i).Eval<Eigen::VectorXd>(context);
}

}  // namespace cairn::systems
