// Uniform acceleration (gravity, a centrifuge): f_I = m_I g.
#pragma once

#include "rkpm/sim/world.hpp"

namespace rkpm::sim {

class BodyForce final : public Term {
 public:
  BodyForce(Body& body, const Vec3& acceleration) : body_(body), g_(acceleration) {}
  std::string name() const override { return "body_force"; }
  void add_forces(World&) override;
  double power(const World&) const override;
  bool distributed() const override { return true; }

 private:
  Body& body_;
  Vec3 g_;
};

}  // namespace rkpm::sim
