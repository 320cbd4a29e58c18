#pragma once
/// Where an interaction (a probe, a haptic device) pushes on a body. It belongs to the problem
/// (model::Problem::interaction), never to the model: blocks whose forces follow it (the surface model's volume
/// penalty with the weights of Arnab & Raja's Eq. 4) read it per evaluation, so one model can serve several
/// problems and threads at once.
#include <hooke/core/types.hpp>

namespace hooke::model {

struct Interaction {
  Vec3 point = Vec3::Zero();      ///< p_f, m
  Vec3 direction = Vec3::Zero();  ///< direction of the interaction force F_f (any length > 0)
  double radius = 0.0;            ///< radius of influence r, m (> 0)
};

/// @throws InvalidArgument unless the radius is > 0 and the direction non-zero (both finite)
void require_valid(const Interaction& interaction);

}  // namespace hooke::model
