// Generated from milk_cartoon_all_small_clorox.pcd by: octopoint-prepare data/scans/milk_cartoon_all_small_clorox.pcd -o build/regenerated-models --name tabletop --axes y-up --crop -0.35,-0.25,-1.1,0.35,0.45,-0.45 --normals
// Do not edit: regenerate it.
#pragma once

#include "octopoint/model.h"

namespace octopoint::models {

// depth 6: 5433 voxels, 2010 node bytes (2.95 bits per point of geometry) + 5433 colour bytes + 5433 normal bytes
// depth 7: 19747 voxels, 7443 node bytes (3.01 bits per point of geometry) + 19747 colour bytes + 19747 normal bytes
// depth 8: 62502 voxels, 27190 node bytes (3.48 bits per point of geometry) + 62502 colour bytes + 62502 normal bytes
extern const ::octopoint::EmbeddedModel tabletop;

}  // namespace octopoint::models
