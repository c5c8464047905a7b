#pragma once

// A mesh on the bus: geometry::Mesh <-> mesh_t (lcmtypes/avc/mesh_t.lcm) as a binary PLY, so the
// per-face cluster ids (`label`) and per-vertex colours travel with it.

#include <avc/mesh_t.hpp>
#include <string>

#include "core/geometry/mesh.h"

namespace avc::messages {

// Frame "world". Same mesh, same bytes. Throws std::invalid_argument naming the mesh when it is
// inconsistent (Mesh::Validate).
avc::mesh_t MeshToMessage(const geometry::Mesh& mesh, const std::string& mesh_id);

// Throws std::invalid_argument naming the mesh when its data does not read as the PLY its
// header announces (encoding, vertex and face counts).
geometry::Mesh MeshFromMessage(const avc::mesh_t& message);

}  // namespace avc::messages
