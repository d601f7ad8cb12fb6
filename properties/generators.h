// Every generator of the property suite, one family per header of properties/generators/. Each mixes random cases
// with hand-picked extremes through rc::gen::weightedOneOf and names its kind, so that the properties' RC_CLASSIFY
// shows the mix. Sizes are drawn uniformly (not scaled by RapidCheck's size), so every case is a full draw.
#pragma once

#include "properties/generators/cameras_and_lenses.h"
#include "properties/generators/clip_space.h"
#include "properties/generators/lights.h"
#include "properties/generators/models.h"
#include "properties/generators/scene_extremes.h"
#include "properties/generators/screen_meshes.h"
#include "properties/generators/square_symmetries.h"
#include "properties/generators/tiling_case.h"
#include "properties/generators/view_space.h"
