// Every module's scene keys, registered before any test reads a scene (as monosph's main does).
#include "assemble.hpp"

namespace {
const bool registered = (monosph::register_modules(), true);
}  // namespace
