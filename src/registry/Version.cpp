#include "mms/mms.h"

namespace mms {

const char* version() { return MMS_VERSION; }

}  // namespace mms
