#pragma once

#include <glissade/body/body.h>
#include <glissade/contact/contact_pair.h>

#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * Refuses, before anything is computed, a scene in which a rigid motion
   * is free: a motion of bodies whose supports leave it free
   * (BodyLinearSystem::free_rigid_motions) that no contact within the alert
   * distance at t = 0 holds, a contact holding the normal direction, and with
   * friction also the tangential one. The InputError names the bodies and
   * the motion; `source` is the scene's file.
   */
  void
  check_free_motions_are_held(
    const std::vector<std::unique_ptr<Body>>        &bodies,
    const std::vector<std::unique_ptr<ContactPair>> &pairs,
    const std::string                               &source);
} // namespace glissade
