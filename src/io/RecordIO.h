#pragma once
// Records of the planning, format "mms-record/1" (docs/formats.md): what `mms plan --record`
// writes and `mms view --record` reads. Written and read here only, so the keys are typed once.
#include <nlohmann/json.hpp>
#include <string>

#include "mms/Planner.h"
#include "mms/Record.h"

namespace mms {

inline constexpr const char* kRecordFormat = "mms-record/1";

/// A record with the run's statistics (its phases and counts, for the chart beside it).
struct RecordFile {
  PlanRecord record;
  PlanStatistics stats;
};

/// The document as text, written item by item (never a whole JSON tree: ten times the file's
/// size). Coordinates, angles and times are written to 1e-6.
std::string recordText(const PlanRecord& record, const PlanStatistics& stats);
/// The same document as JSON (Python's result.record, tests).
nlohmann::json recordToJson(const PlanRecord& record, const PlanStatistics& stats);
void saveRecord(const PlanRecord& record, const PlanStatistics& stats, const std::string& file);

/// Reads and checks a record for a scene of `robots` robots; throws InputError naming the file,
/// the field and the problem.
RecordFile parseRecord(const nlohmann::json& doc, const std::string& source, size_t robots);
RecordFile loadRecord(const std::string& file, size_t robots);

}  // namespace mms
