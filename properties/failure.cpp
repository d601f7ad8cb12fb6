// fail_case: RC_FAIL with the message as its only argument.
#include "properties/failure.h"

#include <rapidcheck.h>

namespace raster::properties {

void fail_case(const std::string& message) { RC_FAIL(message); }

}  // namespace raster::properties
