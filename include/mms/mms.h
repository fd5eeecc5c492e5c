#pragma once
// mms: motion planning via manifold samples, for planar polygonal robots. One include for
// programs that embed it (find_package(mms), target mms::mms); docs/architecture.md.
#include "mms/Certificate.h"
#include "mms/Errors.h"
#include "mms/Geometry.h"
#include "mms/Io.h"
#include "mms/Planner.h"
#include "mms/Scene.h"
#include "mms/Termination.h"

namespace mms {
/// The library's version, "MAJOR.MINOR.PATCH".
const char* version();
}  // namespace mms
