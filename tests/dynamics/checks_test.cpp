// Argument checks: a Data of another model and vectors of the wrong size are named.
#include "dynamics/checks.hpp"

#include <catch2/catch.hpp>

#include "dynamics/model_builder.hpp"

using namespace yardsim::dynamics;

namespace {
// (n links) => a planar revolute chain
Model chain(int n) {
  ModelBuilder b;
  std::string parent = "world";
  for (int i = 0; i < n; ++i) {
    const std::string name = "link" + std::to_string(i);
    b.addBody(name, parent, Joint::revolute(Vector3::UnitZ()),
              Transform::translation(Vector3(i == 0 ? 0.0 : 1.0, 0, 0)),
              boxInertia(1.0, Vector3(1, 0.1, 0.1)));
    parent = name;
  }
  return b.build();
}
}  // namespace

TEST_CASE("a Data fits the model it was made for and no other") {
  const Model two = chain(2), three = chain(3);
  const Data d2(two), d3(three);
  CHECK(fits(two, d2));
  CHECK(fits(three, d3));
  CHECK_FALSE(fits(two, d3));
  CHECK_FALSE(fits(three, d2));
}

TEST_CASE("arguments of the wrong size are refused naming the algorithm and the sizes") {
  const Model m = chain(2);
  const Data d(m), other(chain(3));
  const Eigen::VectorXd q = Eigen::VectorXd::Zero(2), v = Eigen::VectorXd::Zero(2);
  const Eigen::VectorXd wrong = Eigen::VectorXd::Zero(3);
  CHECK_NOTHROW(checkArguments(m, d, q, &v, &v, "aba"));
  CHECK_THROWS_WITH(
      checkArguments(m, d, wrong, &v, nullptr, "aba"),
      Catch::Contains("aba") && Catch::Contains("q has 3 values") && Catch::Contains("nq = 2"));
  CHECK_THROWS_WITH(checkArguments(m, d, q, &wrong, nullptr, "rnea"),
                    Catch::Contains("rnea") && Catch::Contains("v has 3 values"));
  CHECK_THROWS_WITH(checkArguments(m, d, q, &v, &wrong, "rnea"), Catch::Contains("ddq or tau"));
  CHECK_THROWS_WITH(checkArguments(m, other, q, &v, nullptr, "crba"),
                    Catch::Contains("made for another model"));
}
