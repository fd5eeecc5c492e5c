#include "util/Number.h"

#include <cstdio>

namespace mms {

std::string formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace mms
