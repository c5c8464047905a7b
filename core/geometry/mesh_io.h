#pragma once

// Reading and writing triangle meshes: PLY (ascii, binary little/big endian), Wavefront OBJ and
// OFF (OFF, COFF, NOFF, STOFF...). Polygons are triangulated as fans from their first corner.
// Every error is a std::runtime_error whose message starts with the file name and names the
// line or element at fault, e.g. "plant.ply: face 12 refers to vertex 900 of 800".

#include <filesystem>

#include "core/geometry/mesh.h"

namespace avc::geometry {

// Reads a mesh, choosing the format from the extension (.ply, .obj, .off; any case).
//  PLY: vertex x y z, optional red green blue (uchar, or float 0..1), optional texture
//       coordinates (u v, s t, texture_u texture_v, texture_s texture_t); face vertex_indices or
//       vertex_index list, optional int label and material (per-face organ label and material
//       index); other properties and elements are skipped.
//  OBJ: v (with optional r g b floats 0..1), vt, f in the v, v/vt, v//vn and v/vt/vn forms,
//       negative (relative) indices. A vertex used with two different vt gets a copy appended.
//  OFF: optional C (colour), N (normal), ST (texture) prefixes, '#' comments.
Mesh ReadMesh(const std::filesystem::path& path);

// Writes PLY: vertices (float x y z), colours (uchar red green blue) if present, uvs (float u v)
// if present, faces (uchar int vertex_indices), per-face int label and int material if present.
// Reading the file back gives the same mesh exactly (floats are written bit-exact in binary and
// in their shortest round-trip decimal form in ascii). Same mesh → same bytes.
void WriteMeshPly(const std::filesystem::path& path, const Mesh& mesh, bool binary = true);

// Writes OBJ: v (with r g b when coloured), vt when uvs are present (one per vertex, same index),
// f. Labels and materials are not stored. Round-trips vertices, colours, uvs and faces exactly.
void WriteMeshObj(const std::filesystem::path& path, const Mesh& mesh);

// Writes OFF (COFF with r g b a uchar when coloured). Round-trips vertices, colours and faces.
void WriteMeshOff(const std::filesystem::path& path, const Mesh& mesh);

}  // namespace avc::geometry
