#include "sim/render/frame_geometry.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <stdexcept>

#include "sim/render/face_tessellator.h"

namespace avc::sim {
namespace {

// Faces are processed in fixed chunks whose outputs are joined in chunk order, so the triangle
// order (and with it every tie-break) is the same for any number of threads.
constexpr size_t kFacesPerChunk = 2048;
constexpr size_t kVerticesPerChunk = 8192;

// Area-weighted vertex normals in the world frame; zero where no face with area touches.
void VertexNormals(const geometry::Mesh& mesh, std::vector<Eigen::Vector3d>* sum,
                   std::vector<Eigen::Vector3f>* normals) {
  sum->assign(mesh.vertices.size(), Eigen::Vector3d::Zero());
  for (const Eigen::Vector3i& f : mesh.faces) {
    const Eigen::Vector3d a = mesh.vertices[f[0]].cast<double>();
    const Eigen::Vector3d n =
        (mesh.vertices[f[1]].cast<double>() - a).cross(mesh.vertices[f[2]].cast<double>() - a);
    for (int k = 0; k < 3; ++k) (*sum)[f[k]] += n;
  }
  normals->resize(sum->size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, sum->size(), kVerticesPerChunk),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t i = range.begin(); i != range.end(); ++i) {
                        const double norm = (*sum)[i].norm();
                        (*normals)[i] = norm > 0 ? Eigen::Vector3f(((*sum)[i] / norm).cast<float>())
                                                 : Eigen::Vector3f::Zero();
                      }
                    });
}

// Shading data of a face with vertices p (camera frame); false for a face without area.
bool SetUpFace(const geometry::Mesh& mesh, size_t face, const std::array<Eigen::Vector3d, 3>& p,
               const Eigen::Matrix3d& R_world_cam, const std::vector<Eigen::Vector3f>& normals,
               FaceShading* shading) {
  const Eigen::Vector3d e1 = p[1] - p[0], e2 = p[2] - p[0];
  const Eigen::Vector3d n = e1.cross(e2);
  const double nn = n.squaredNorm();
  if (!(nn > 0) || !std::isfinite(nn)) return false;
  shading->plane_normal = n / std::sqrt(nn);
  shading->plane_offset = shading->plane_normal.dot(p[0]);
  shading->origin = p[0];
  shading->bary1 = (e2.cross(n) / nn).cast<float>();
  shading->bary2 = (n.cross(e1) / nn).cast<float>();
  const Eigen::Vector3i& f = mesh.faces[face];
  const Eigen::Vector3f face_normal = (R_world_cam * shading->plane_normal).cast<float>();
  for (int k = 0; k < 3; ++k) {
    shading->uv[k] = mesh.uvs[f[k]];
    shading->normal[k] = normals.empty() || normals[f[k]].isZero() ? face_normal : normals[f[k]];
  }
  shading->material = mesh.face_materials[face];
  shading->label = mesh.face_labels[face];
  return true;
}

}  // namespace

void ValidateScene(const Scene& scene) {
  const geometry::Mesh& mesh = scene.mesh;
  const std::string problem = mesh.Validate();
  if (!problem.empty()) {
    throw std::invalid_argument(fmt::format("scene '{}': invalid mesh: {}", scene.name, problem));
  }
  if (mesh.faces.empty()) return;
  auto missing = [&](const char* what) {
    return std::invalid_argument(
        fmt::format("scene '{}': the mesh has no {}; the renderer needs them for every {}",
                    scene.name, what, std::string(what) == "uvs" ? "vertex" : "face"));
  };
  if (mesh.uvs.empty()) throw missing("uvs");
  if (mesh.face_labels.empty()) throw missing("face_labels");
  if (mesh.face_materials.empty()) throw missing("face_materials");
  for (size_t i = 0; i < mesh.faces.size(); ++i) {
    const int32_t material = mesh.face_materials[i];
    if (material < 0 || static_cast<size_t>(material) >= scene.materials.size()) {
      throw std::invalid_argument(
          fmt::format("scene '{}': face {} uses material {} but the scene has {} material(s)",
                      scene.name, i, material, scene.materials.size()));
    }
  }
}

void BuildFrameGeometry(const Scene& scene, const camera::Camera& camera, const LensModel& lens,
                        const RenderOptions& options, FrameGeometry* frame) {
  const geometry::Mesh& mesh = scene.mesh;
  const Eigen::Matrix3d R = camera.T_cam_world.linear();
  const Eigen::Vector3d t = camera.T_cam_world.translation();

  const SampleGrid grid{options.samples_per_pixel_axis};
  const FaceTessellator tessellator(lens, grid, options.near_clip_m, options.max_edge_error_px);
  // Each vertex is transformed and projected once, not once per face using it.
  std::vector<ScreenVertex>& screen = frame->vertices;
  std::vector<uint8_t>& outcodes = frame->outcodes;
  screen.resize(mesh.vertices.size());
  outcodes.resize(mesh.vertices.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, screen.size(), kVerticesPerChunk),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t i = range.begin(); i != range.end(); ++i) {
                        const Eigen::Vector3d p = R * mesh.vertices[i].cast<double>() + t;
                        outcodes[i] = tessellator.Outcode(p);
                        if (outcodes[i] == 0) {
                          screen[i] = tessellator.MakeVertex(p);
                        } else {
                          screen[i].p = p;
                        }
                      }
                    });
  std::vector<Eigen::Vector3f>& normals = frame->normals;
  if (options.smooth_shading) {
    VertexNormals(mesh, &frame->normal_sums, &normals);
  } else {
    normals.clear();
  }

  const size_t num_faces = mesh.faces.size();
  const size_t num_chunks = (num_faces + kFacesPerChunk - 1) / kFacesPerChunk;
  std::vector<FrameChunk>& chunks = frame->chunks;
  chunks.resize(num_chunks);
  const Eigen::Matrix3d R_world_cam = R.transpose();
  tbb::parallel_for(size_t{0}, num_chunks, [&](size_t chunk) {
    FrameChunk& out = chunks[chunk];
    out.triangles.clear();
    out.shadings.clear();
    out.stats = {};
    const size_t end = std::min(num_faces, (chunk + 1) * kFacesPerChunk);
    for (size_t face = chunk * kFacesPerChunk; face < end; ++face) {
      const Eigen::Vector3i& f = mesh.faces[face];
      const size_t before = out.triangles.size();
      const FaceTessellator::Outcome outcome =
          tessellator.Tessellate({&screen[f[0]], &screen[f[1]], &screen[f[2]]},
                                 {outcodes[f[0]], outcodes[f[1]], outcodes[f[2]]},
                                 static_cast<int32_t>(out.shadings.size()), &out.triangles);
      if (out.triangles.size() == before) continue;
      const std::array<Eigen::Vector3d, 3> p = {screen[f[0]].p, screen[f[1]].p, screen[f[2]].p};
      FaceShading shading;
      if (!SetUpFace(mesh, face, p, R_world_cam, normals, &shading)) {
        out.triangles.resize(before);  // no area: nothing to see
        continue;
      }
      out.shadings.push_back(shading);
      out.stats.clipped_faces += outcome.clipped;
      out.stats.subdivided_faces += outcome.subdivided;
    }
  });
  // Join the chunks in order (in parallel: each copies into its own slots).
  frame->stats = {};
  frame->stats.faces = num_faces;
  std::vector<size_t> triangle_offset(num_chunks + 1, 0), shading_offset(num_chunks + 1, 0);
  for (size_t chunk = 0; chunk < num_chunks; ++chunk) {
    triangle_offset[chunk + 1] = triangle_offset[chunk] + chunks[chunk].triangles.size();
    shading_offset[chunk + 1] = shading_offset[chunk] + chunks[chunk].shadings.size();
    frame->stats.clipped_faces += chunks[chunk].stats.clipped_faces;
    frame->stats.subdivided_faces += chunks[chunk].stats.subdivided_faces;
  }
  frame->triangles.resize(triangle_offset.back());
  frame->shadings.resize(shading_offset.back());
  tbb::parallel_for(size_t{0}, num_chunks, [&](size_t chunk) {
    const int32_t shift = static_cast<int32_t>(shading_offset[chunk]);
    RasterTriangle* triangle = frame->triangles.data() + triangle_offset[chunk];
    for (const RasterTriangle& local : chunks[chunk].triangles) {
      *triangle = local;
      triangle->shading += shift;
      ++triangle;
    }
    std::copy(chunks[chunk].shadings.begin(), chunks[chunk].shadings.end(),
              frame->shadings.begin() + static_cast<std::ptrdiff_t>(shading_offset[chunk]));
  });
  frame->stats.raster_triangles = frame->triangles.size();
}

}  // namespace avc::sim
