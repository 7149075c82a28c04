// Umbrella header of sweepcdt::predicates.
#pragma once
#include "sweepcdt/predicates/occlusion.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"
#include "sweepcdt/predicates/ray.h"
#include "sweepcdt/predicates/rotary.h"
#include "sweepcdt/predicates/sign.h"
#include "sweepcdt/predicates/stats.h"
#include "sweepcdt/predicates/sweep_keys.h"
#include "sweepcdt/predicates/sweep_sides.h"
#include "sweepcdt/predicates/vertex.h"
#include "sweepcdt/predicates/exact_sum.h"
#include "sweepcdt/predicates/ray_box.h"
