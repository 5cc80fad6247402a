// The scene job (docs/scenes.md): every impact of a scene file to the scene's
// tolerance, with the error map and the committed surrogate of its law where they
// serve; one row per impact as CSV, or one JSON object. `viscor scene` and the
// Python module's viscor.scene call it.
#pragma once

#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/scene_file.hpp>

#include <string>

namespace viscor::jobs {

/// What a scene run produced: the output (CSV rows, or the JSON object when asked)
/// and a readable summary of how it was computed.
struct scene_result {
  std::string body;     ///< CSV, or JSON text
  json object;          ///< the JSON object (as_json only)
  std::string summary;  ///< law, bead, damping, load, methods used, time
};

/// Evaluates every impact of `file` (read from `path`, named in the output).
/// `error_maps`: a directory of error maps given by the caller ("" for the scene's
/// error_maps, then $VISCOR_ERROR_MAPS, then the data directory's error_maps).
scene_result run_scene_file(const scene_file& file, const std::string& path, const std::string& error_maps,
                            bool as_json);

}  // namespace viscor::jobs
