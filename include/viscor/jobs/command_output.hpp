// What a one-shot job reports: the readable summary a terminal shows and the JSON
// object (`--json`, Python) with the same content. Jobs build both in one place so
// the two forms cannot drift apart; front ends only choose which one to print.
#pragma once

#include <viscor/jobs/json_fields.hpp>

#include <string>

namespace viscor::jobs {

/// A job's result in its two forms.
struct command_output {
  std::string text;  ///< the readable summary, lines ending in '\n'
  json object;       ///< the same content as one JSON object (docs/json-schema.md)
};

}  // namespace viscor::jobs
