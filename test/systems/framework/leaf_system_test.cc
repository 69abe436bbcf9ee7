#include "cairn/systems/framework/leaf_system.h"

#include <string>

#include <gtest/gtest.h>

#include "expect_throws.h"
#include "test_systems.h"

namespace cairn::systems {
namespace {

using test::KitchenSink;

TEST(LeafSystemTest, DeclaresPortsStateAndParameters) {
  KitchenSink system;
  system.set_name("sink");
  EXPECT_EQ(system.num_input_ports(), 2);
  EXPECT_EQ(system.num_output_ports(), 4);
  EXPECT_EQ(system.GetInputPort("label").get_data_type(), PortDataType::kAbstract);
  EXPECT_EQ(system.get_output_port(0).size(), 2);
  EXPECT_EQ(system.num_continuous_states(), 2);
  auto context = system.CreateDefaultContext();
  EXPECT_EQ(context->get_discrete_state(0), Eigen::Vector2d(10.0, 20.0));
  EXPECT_EQ(context->get_abstract_state<int>(0), 42);
  EXPECT_EQ(context->get_abstract_parameter<std::string>(0), "param");
  EXPECT_EQ(context->get_continuous_state_vector(), Eigen::Vector2d(1.0, -1.0));
}

TEST(LeafSystemTest, EvaluatesOutputsFromFixedInputs) {
  KitchenSink system;
  auto context = system.CreateDefaultContext();
  system.get_input_port(0).FixValue(context.get(), Eigen::Vector2d(1.0, 2.0));
  system.get_input_port(1).FixValue(context.get(), "hello");
  EXPECT_EQ(system.GetOutputPort("sum").Eval<Eigen::VectorXd>(*context), Eigen::Vector2d(11.5, 22.25));
  EXPECT_EQ(system.GetOutputPort("text").Eval<std::string>(*context), "hello!");
  Eigen::VectorXd derivatives;
  system.CalcTimeDerivatives(*context, &derivatives);
  EXPECT_EQ(derivatives, Eigen::Vector2d(-1.0, 1.0));
}

TEST(LeafSystemTest, CachedOutputIsComputedOnceUntilAPrerequisiteChanges) {
  KitchenSink system;
  auto context = system.CreateDefaultContext();
  system.get_input_port(0).FixValue(context.get(), Eigen::Vector2d(1.0, 2.0));
  const OutputPort& sum = system.GetOutputPort("sum");
  const DependencyTicket sum_ticket = system.output_port_ticket(sum.get_index());
  const DependencyTicket time_output = system.output_port_ticket(1);
  const DependencyTicket everything = system.output_port_ticket(2);

  for (int i = 0; i < 5; ++i) sum.Eval<Eigen::VectorXd>(*context);
  EXPECT_EQ(context->num_calculations(sum_ticket), 1);

  // Time and continuous state are not prerequisites of `sum`, but are of `everything`.
  system.get_output_port(2).Eval<Eigen::VectorXd>(*context);
  context->SetTime(1.0);
  context->get_mutable_continuous_state_vector()[0] = 3.0;
  sum.Eval<Eigen::VectorXd>(*context);
  system.get_output_port(2).Eval<Eigen::VectorXd>(*context);
  EXPECT_EQ(context->num_calculations(sum_ticket), 1);
  EXPECT_EQ(context->num_calculations(everything), 2);

  // Each declared prerequisite invalidates it.
  context->get_mutable_discrete_state(0)[1] = 0.0;
  EXPECT_EQ(sum.Eval<Eigen::VectorXd>(*context), Eigen::Vector2d(11.5, 2.25));
  EXPECT_EQ(context->num_calculations(sum_ticket), 2);
  context->get_mutable_numeric_parameter(0)[0] = 0.0;
  sum.Eval<Eigen::VectorXd>(*context);
  EXPECT_EQ(context->num_calculations(sum_ticket), 3);
  system.get_input_port(0).FixValue(context.get(), Eigen::Vector2d(0.0, 0.0));
  sum.Eval<Eigen::VectorXd>(*context);
  EXPECT_EQ(context->num_calculations(sum_ticket), 4);

  // The label input does not affect `sum`; time affects only the time output.
  system.get_input_port(1).FixValue(context.get(), "other");
  sum.Eval<Eigen::VectorXd>(*context);
  EXPECT_EQ(context->num_calculations(sum_ticket), 4);
  system.get_output_port(1).Eval<Eigen::VectorXd>(*context);
  context->SetTime(2.0);
  EXPECT_EQ(system.get_output_port(1).Eval<Eigen::VectorXd>(*context)[0], 2.0);
  EXPECT_EQ(context->num_calculations(time_output), 2);
}

TEST(LeafSystemTest, ResultsAreIdenticalWithCachingOff) {
  KitchenSink system;
  auto cached = system.CreateDefaultContext();
  auto uncached = system.CreateDefaultContext();
  uncached->DisableCaching();
  for (auto* context : {cached.get(), uncached.get()}) {
    system.get_input_port(0).FixValue(context, Eigen::Vector2d(3.0, 4.0));
    system.get_input_port(1).FixValue(context, "x");
  }
  for (int step = 0; step < 3; ++step) {
    for (auto* context : {cached.get(), uncached.get()}) {
      context->SetTime(0.5 * step);
      context->get_mutable_discrete_state(0)[0] = step;
    }
    for (int port = 0; port < 3; ++port) {
      EXPECT_EQ(system.get_output_port(port).Eval<Eigen::VectorXd>(*cached),
                system.get_output_port(port).Eval<Eigen::VectorXd>(*uncached));
    }
  }
  // Without caching every Eval computes.
  const auto ticket = system.output_port_ticket(0);
  const int64_t before = uncached->num_calculations(ticket);
  system.get_output_port(0).Eval<Eigen::VectorXd>(*uncached);
  system.get_output_port(0).Eval<Eigen::VectorXd>(*uncached);
  EXPECT_EQ(uncached->num_calculations(ticket), before + 2);
  uncached->EnableCaching();
  system.get_output_port(0).Eval<Eigen::VectorXd>(*uncached);
  system.get_output_port(0).Eval<Eigen::VectorXd>(*uncached);
  EXPECT_EQ(uncached->num_calculations(ticket), before + 3);
}

TEST(LeafSystemTest, DirectFeedthroughFollowsDeclaredPrerequisites) {
  KitchenSink system;
  EXPECT_TRUE(system.HasDirectFeedthrough(0, 0));   // sum depends on u.
  EXPECT_FALSE(system.HasDirectFeedthrough(1, 0));  // ... not on label.
  EXPECT_FALSE(system.HasDirectFeedthrough(0, 1));  // time output depends on time only.
  EXPECT_TRUE(system.HasDirectFeedthrough(1, 2));   // default prerequisites: everything.
  EXPECT_TRUE(system.HasDirectFeedthrough(1, 3));
  EXPECT_FALSE(system.HasDirectFeedthrough(0, 3));
}

class CacheChain final : public LeafSystem {
 public:
  CacheChain() {
    const auto& u = DeclareVectorInputPort("u", 1);
    squared_ = DeclareCacheEntry(
        "squared", Value<double>(0.0),
        [this](const Context& context, AbstractValue* value) {
          const double x = get_input_port().Eval<Eigen::VectorXd>(context)[0];
          value->set_value(x * x);
        },
        {u.ticket()});
    DeclareVectorOutputPort(
        "y", 1, [this](const Context& context, Eigen::VectorXd* y) { (*y)[0] = EvalCacheEntry<double>(context, squared_) + 1.0; },
        {cache_entry_ticket(squared_)});
  }
  int squared_;
};

TEST(LeafSystemTest, CacheEntriesChainAndCarryFeedthrough) {
  CacheChain system;
  EXPECT_TRUE(system.HasDirectFeedthrough(0, 0));
  auto context = system.CreateDefaultContext();
  system.get_input_port().FixValue(context.get(), Eigen::VectorXd::Constant(1, 3.0));
  EXPECT_EQ(system.get_output_port().Eval<Eigen::VectorXd>(*context)[0], 10.0);
  system.get_input_port().FixValue(context.get(), Eigen::VectorXd::Constant(1, 2.0));
  EXPECT_EQ(system.get_output_port().Eval<Eigen::VectorXd>(*context)[0], 5.0);
  EXPECT_EQ(context->num_calculations(system.cache_entry_ticket(0)), 2);
}

TEST(LeafSystemTest, RejectsBadInputsWithMessagesThatSayWhatToDo) {
  KitchenSink system;
  system.set_name("sink");
  auto context = system.CreateDefaultContext();
  CAIRN_EXPECT_THROWS_WITH(system.GetOutputPort("sum").Eval<Eigen::VectorXd>(*context), std::logic_error,
                           "input port 'u' of system 'sink' has no value", "FixValue");
  CAIRN_EXPECT_THROWS_WITH(system.get_input_port(0).FixValue(context.get(), Eigen::Vector3d::Zero()),
                           std::invalid_argument, "input port 'u' of system 'sink' (vector of size 2)",
                           "a vector of size 3");
  CAIRN_EXPECT_THROWS_WITH(system.get_input_port(1).FixValue(context.get(), 3), std::invalid_argument,
                           "abstract value of type std::string", "a value of type int");
  CAIRN_EXPECT_THROWS_WITH(system.GetInputPort("lable"), std::invalid_argument, "no input port named 'lable'",
                           "did you mean 'label'");
  CAIRN_EXPECT_THROWS_WITH(system.get_output_port(9), std::out_of_range, "4 output port(s)", "index 9");
  CAIRN_EXPECT_THROWS_WITH(system.GetOutputPort("time").Eval<std::string>(*context), std::logic_error,
                           "output port 'time' of system 'sink' carries Eigen::VectorXd",
                           "evaluated as std::string", "use Eval<Eigen::VectorXd>()");
}

TEST(LeafSystemTest, RejectsAContextItDidNotCreate) {
  KitchenSink a;
  KitchenSink b;
  a.set_name("a");
  b.set_name("b");
  auto context_of_b = b.CreateDefaultContext();
  CAIRN_EXPECT_THROWS_WITH(a.get_output_port(1).Eval<Eigen::VectorXd>(*context_of_b), std::logic_error,
                           "A Context created by system 'b' was passed to system 'a'", "CreateDefaultContext()");
  Eigen::VectorXd derivatives;
  CAIRN_EXPECT_THROWS_WITH(a.CalcTimeDerivatives(*context_of_b, &derivatives), std::logic_error, "system 'a'");
}

class BadDeclarations final : public LeafSystem {
 public:
  explicit BadDeclarations(int which) {
    set_name("bad");
    if (which == 0) {
      DeclareVectorInputPort("u", 1);
      DeclareVectorInputPort("u", 2);
    } else if (which == 1) {
      DeclarePeriodicPublishEvent(0.0, 0.0, [](const Context&) {});
    } else if (which == 2) {
      DeclareVectorOutputPort("y", 1, [](const Context&, Eigen::VectorXd*) {}, {DependencyTicket(99)});
    } else if (which == 3) {
      DeclareVectorOutputPort("y", 1, [](const Context&, Eigen::VectorXd* y) { y->resize(3); });
    }
  }
};

TEST(LeafSystemTest, RejectsBadDeclarations) {
  CAIRN_EXPECT_THROWS_WITH(BadDeclarations(0), std::logic_error, "already has an input port named 'u'");
  CAIRN_EXPECT_THROWS_WITH(BadDeclarations(1), std::invalid_argument, "period > 0");
  CAIRN_EXPECT_THROWS_WITH(BadDeclarations(2), std::invalid_argument, "prerequisite ticket 99",
                           "declare what it depends on first");
  BadDeclarations resizing(3);
  auto context = resizing.CreateDefaultContext();
  CAIRN_EXPECT_THROWS_WITH(resizing.get_output_port().Eval<Eigen::VectorXd>(*context), std::logic_error,
                           "resized its output to 3 (declared size 1)");
}

class StorageSystem final : public LeafSystem {
 public:
  StorageSystem() { index_ = DeclarePerContextStorage(Value<int>(0)); }
  void Bump(const Context& context) const { ++GetMutablePerContextStorage<int>(context, index_); }
  int Get(const Context& context) const { return GetPerContextStorage<int>(context, index_); }
  int index_;
};

TEST(LeafSystemTest, PerContextStorageIsPerContextAndCloned) {
  StorageSystem system;
  auto a = system.CreateDefaultContext();
  auto b = system.CreateDefaultContext();
  system.Bump(*a);
  system.Bump(*a);
  EXPECT_EQ(system.Get(*a), 2);
  EXPECT_EQ(system.Get(*b), 0);
  EXPECT_EQ(system.Get(*a->Clone()), 2);
}

// A discrete-time system whose output is its state (the shape of a physics plant's `state` port).
class StateHolder final : public LeafSystem {
 public:
  explicit StateHolder(bool declare_state) {
    if (declare_state) DeclareDiscreteState(Eigen::Vector2d(1.0, 2.0));
    DeclareVectorInputPort("u", 1);
    DeclareStateOutputPort("state", 0);
  }
};

TEST(LeafSystemTest, StateOutputPortIsTheStateWithoutFeedthrough) {
  StateHolder system(true);
  auto context = system.CreateDefaultContext();
  EXPECT_EQ(system.get_output_port(0).Eval<Eigen::VectorXd>(*context), Eigen::Vector2d(1.0, 2.0));
  EXPECT_FALSE(system.HasDirectFeedthrough(0, 0));
  context->SetDiscreteState(0, Eigen::Vector2d(3.0, 4.0));
  EXPECT_EQ(system.get_output_port(0).Eval<Eigen::VectorXd>(*context), Eigen::Vector2d(3.0, 4.0));
  CAIRN_EXPECT_THROWS_WITH(StateHolder(false), std::invalid_argument,
                           "DeclareStateOutputPort('state'): discrete state group 0 is not declared");
}

}  // namespace
}  // namespace cairn::systems
