// Tests of the model registries: a new cushion model is one class and one registration (the toy
// mirror model below lives in this file alone, and a scene that names it runs through it), names
// are unique, and a group's keys are refused naming the models that read them.
#include "engine/models/model_registry.h"

#include <gtest/gtest.h>

#include "engine/io/scene.h"
#include "engine/models/cushion_exact_model.h"
#include "tests/engine/error_test_support.h"
#include "tests/engine/models/model_test_support.h"

namespace baize::engine {
namespace {

// Rounding of a closed-form rebound through the loop's frame rotation, relative.
constexpr double kClosedFormRelative = 1e-12;

// A toy cushion model: the normal speed reversed and scaled by `factor`, the rest kept.
class MirrorCushionModel final : public CushionContactModel {
 public:
  explicit MirrorCushionModel(double factor) : factor_(factor) {}
  const char* name() const override { return "mirror"; }
  void validate(const SimulationParams&) const override {
    if (!(factor_ > 0 && factor_ <= 1)) throw std::invalid_argument("mirror factor out of (0, 1]");
  }
  physics::BallVelocity resolve(const SimulationParams&,
                                const physics::BallVelocity& incoming) const override {
    physics::BallVelocity after = incoming;
    after.v.y() = -factor_ * incoming.v.y();
    return after;
  }
  bool worthSolvingAhead() const override { return false; }
  RigidCushionContact rigidContact(const SimulationParams&) const override { return {}; }
  nlohmann::json parametersJson() const override {
    return {{"model", name()}, {"mirror_factor", factor_}};
  }

 private:
  double factor_;
};

ModelEntry<CushionContactModel> mirrorCushionModel() {
  return {"mirror", {"mirror_factor"}, [](const ModelDefaults&, const JsonReader* parameters) {
            const double factor = parameters && parameters->has("mirror_factor")
                                      ? parameters->finiteNumber("mirror_factor")
                                      : 1.0;
            return std::make_shared<const MirrorCushionModel>(factor);
          }};
}

// The one registration, done once for the whole test program.
void registerMirrorOnce() {
  static const bool registered = [] {
    cushionModels().add(mirrorCushionModel());
    return true;
  }();
  (void)registered;
}

TEST(ModelRegistry, AToyCushionModelRegisteredInATestRunsAScene) {
  registerMirrorOnce();
  const nlohmann::json doc = {
      {"table", "pool-9ft"},
      {"ball_set", "pool"},
      {"balls", {{"cue", {0.5, 0.0}}}},
      {"shot", {{"heading_deg", 0}, {"speed_mps", 1.5}, {"height", 0.4}}},
      {"physics", {{"cushion", {{"model", "mirror"}, {"mirror_factor", 0.5}}}}}};
  const Scene scene = sceneFromJson(doc, "toy.json");
  const SceneRun run = runScene(scene);
  const Event& hit = firstEventOf(run.result, EventKind::Cushion);
  const double V = hit.before[0].velocity.x();
  ASSERT_GT(V, 0);
  EXPECT_NEAR(hit.after[0].velocity.x(), -0.5 * V, kClosedFormRelative * V) << "v_y' = -0.5 v_y";
  EXPECT_NEAR(hit.after[0].velocity.y(), hit.before[0].velocity.y(), kClosedFormRelative * V);
  const SimulationParams p = simulationParamsFor(scene);
  EXPECT_EQ(physicsJson(p, cueStrikeParamsFor(scene))["cushion"]["mirror_factor"], 0.5);
  // Its key belongs to it alone.
  EXPECT_MENTIONS(invalidArgumentMessage([] {
                    cushionModel({{"mirror_factor", 0.5}});
                  }),
                  "it applies only to model \"mirror\"");
  // Refusals from its checks carry the file and group like any model's.
  nlohmann::json bad = doc;
  bad["physics"]["cushion"]["mirror_factor"] = 2;
  EXPECT_MENTIONS(invalidArgumentMessage([&] { sceneFromJson(bad, "toy.json"); }),
                  "toy.json: physics.cushion: mirror factor out of (0, 1]");
}

TEST(ModelRegistry, ListsTheBuiltInModelsByTheirSceneNames) {
  const std::vector<std::string> cushions = cushionModels().names();
  EXPECT_EQ(std::vector<std::string>(cushions.begin(), cushions.begin() + 4),
            (std::vector<std::string>{"exact", "paper", "simple", "tabulated"}));
  EXPECT_EQ(ballBallModels().names(), (std::vector<std::string>{"frictional", "mathavan2014"}));
  EXPECT_EQ(cushionModels().defaultName(), "tabulated");
  EXPECT_STREQ(poolSimulationParams().cushion->name(), "tabulated");
  EXPECT_STREQ(poolSimulationParams().ball_ball->name(), "frictional");
}

TEST(ModelRegistry, ANameTakenOrUnknownIsRefused) {
  EXPECT_MENTIONS(invalidArgumentMessage([] { cushionModels().add(exactCushionModel()); }),
                  "cushion model \"exact\" is not allowed");
  EXPECT_MENTIONS(invalidArgumentMessage([] { cushionModels().make("rigid", ModelDefaults{}); }),
                  "cushion model \"rigid\" is not allowed: it must be \"exact\", \"paper\"");
  EXPECT_MENTIONS(invalidArgumentMessage([] {
                    cushionModel({{"model", "rigid"}});
                  }),
                  "test.json: physics.cushion.model = \"rigid\" is not allowed");
  EXPECT_MENTIONS(invalidArgumentMessage([] {
                    cushionModel({{"modle", "exact"}});
                  }),
                  "physics.cushion.modle = \"exact\" is not allowed: unknown key");
}

TEST(ModelRegistry, AKeyOfAnotherModelNamesTheModelsThatReadIt) {
  const std::string message = invalidArgumentMessage([] {
    cushionModel({{"model", "simple"}, {"restitution", 0.9}});
  });
  EXPECT_MENTIONS(message, "it applies only to model \"exact\", \"paper\" or \"tabulated\"");
  EXPECT_MENTIONS(message, "model \"simple\" takes simple_restitution");
  EXPECT_MENTIONS(message, "(the model here is \"simple\")");
}

TEST(ModelRegistry, ChangedKeepsEveryOtherParameter) {
  const auto paper = cushionModel({{"model", "paper"}, {"friction", 0.1}, {"paper_steps", 300}});
  const auto more_steps = cushionModels().changed(*paper, {{"paper_steps", 900}}, "test");
  nlohmann::json expected = paper->parametersJson();
  expected["paper_steps"] = 900;
  EXPECT_EQ(more_steps->parametersJson(), expected);
}

}  // namespace
}  // namespace baize::engine
