// The meeting table: which families' manifolds meet, and by which rule. Adding a family adds
// its rows here.
#include "manifolds/Compound.h"
#include "manifolds/Manifold.h"
#include "manifolds/OneRobot.h"
#include "manifolds/Pivot.h"

namespace mms {

namespace {
std::vector<MeetEntry>& table() {
  static std::vector<MeetEntry> rules{
      {&SliceManifold::kFamily, &LineManifold::kFamily, meetOneRobot},
      {&SliceManifold::kFamily, &SliceManifold::kFamily, meetOneRobot},
      {&LineManifold::kFamily, &LineManifold::kFamily, meetOneRobot},
      {&CompoundSliceManifold::kFamily, &CompoundLineManifold::kFamily, meetCompound},
      {&CompoundSliceManifold::kFamily, &SliceManifold::kFamily, meetCompoundOneRobot},
      {&CompoundSliceManifold::kFamily, &LineManifold::kFamily, meetCompoundOneRobot},
      {&CompoundLineManifold::kFamily, &SliceManifold::kFamily, meetCompoundOneRobot},
      {&CompoundLineManifold::kFamily, &LineManifold::kFamily, meetCompoundOneRobot},
      {&PivotLineManifold::kFamily, &SliceManifold::kFamily, meetPivotSlice},
  };
  return rules;
}
}  // namespace

const std::vector<MeetEntry>& meetRules() { return table(); }

void addMeetRule(const MeetEntry& entry) { table().push_back(entry); }

bool meet(const Manifold& a, const Manifold& b, Config& at) {
  const ManifoldFamily *fa = &a.family(), *fb = &b.family();
  for (const MeetEntry& e : table()) {
    if (e.a == fa && e.b == fb) return e.rule(a, b, at);
    if (e.a == fb && e.b == fa) return e.rule(b, a, at);
  }
  return false;
}

std::optional<Config> meetingPoint(const Manifold& a, const Manifold& b) {
  Config at;
  if (!meet(a, b, at)) return std::nullopt;
  return at;
}

}  // namespace mms
