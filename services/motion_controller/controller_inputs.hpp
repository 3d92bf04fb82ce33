// What the unicycle controllers of motion_controller share (papers 000 and 003;
// docs/algorithms/unicycle.md): the planar reference input and the `feedback` key.
#pragma once

#include <string>
#include <vector>

#include "plexus/algorithms/unicycle/figure_eight_reference.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/scenario/component.hpp"

namespace plexus::scenario {

/// The fields of a `reference` input (PlanarReference): position, velocity, acceleration.
inline const std::vector<std::string> kReferenceFields{"x", "y", "dx", "dy", "ddx", "ddy"};

/// A `reference` input's sample.
algorithms::ReferenceSample reference_sample(const InputPort& in);

/// Required key with two allowed values: true for `second`.
bool is_second(const YamlMap& p, const std::string& key, const std::string& first, const std::string& second);

}  // namespace plexus::scenario
