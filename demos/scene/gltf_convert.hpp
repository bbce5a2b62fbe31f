// Internal: conversion of a validated tinygltf::Model (validateModel() passed) into a Scene. Each
// step reads accessor data through viewAccessor() and checks the values it reads: finite floats,
// index and joint ranges, key times in order, counts that agree.
#pragma once
#include "load_context.hpp"

#include <tiny_gltf.h>

namespace rrc::scene::detail {

Result<void> convertMeshes(const tinygltf::Model& model, Scene& scene, LoadContext& context);
// Moves decoded image pixels out of `model`.
void convertMaterials(tinygltf::Model& model, Scene& scene);
// Nodes, the default scene's roots and cameras.
void convertNodes(const tinygltf::Model& model, Scene& scene);
Result<void> convertSkins(const tinygltf::Model& model, Scene& scene, LoadContext& context);
Result<void> convertAnimations(const tinygltf::Model& model, Scene& scene, LoadContext& context);
// Every joint index of a skinned node's mesh is below its skin's joint count.
Result<void> checkSkinnedMeshes(const Scene& scene);

} // namespace rrc::scene::detail
