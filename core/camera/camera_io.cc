#include "core/camera/camera_io.h"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace avc::camera {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void Fail(const fs::path& path, const std::string& where, const std::string& what) {
  throw std::runtime_error(fmt::format("{}{}: {}", path.string(), where, what));
}

std::ofstream OpenForWriting(const fs::path& path) {
  std::ofstream out(path, std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  // Round-trip precision for doubles.
  out.precision(17);
  return out;
}

void CheckWritten(std::ofstream& out, const fs::path& path) {
  out.flush();
  if (!out) throw std::runtime_error("error writing " + path.string());
}

std::string CheckCamera(const NamedCamera& named) {
  std::string problem = named.camera.intrinsics.Validate();
  if (problem.empty() && !named.camera.T_cam_world.matrix().allFinite()) {
    problem = "pose is not finite";
  }
  if (problem.empty() && named.name.empty()) problem = "name is empty";
  return problem;
}

}  // namespace

nlohmann::ordered_json CameraToJson(const NamedCamera& named) {
  if (const std::string problem = CheckCamera(named); !problem.empty()) {
    throw std::invalid_argument(fmt::format("camera '{}': {}", named.name, problem));
  }
  const Intrinsics& k = named.camera.intrinsics;
  std::vector<double> pose;
  const Eigen::Matrix4d m = named.camera.T_cam_world.matrix();
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) pose.push_back(m(r, c));
  }
  return {
      {"name", named.name}, {"width", k.width}, {"height", k.height}, {"fx", k.fx},
      {"fy", k.fy},         {"cx", k.cx},       {"cy", k.cy},         {"distortion", k.distortion},
      {"T_cam_world", pose}};
}

NamedCamera CameraFromJson(const nlohmann::json& entry, const std::string& default_name) {
  try {
    NamedCamera named;
    named.name = entry.value("name", default_name);
    Intrinsics& k = named.camera.intrinsics;
    k.width = entry.at("width").get<int>();
    k.height = entry.at("height").get<int>();
    k.fx = entry.at("fx").get<double>();
    k.fy = entry.at("fy").get<double>();
    k.cx = entry.at("cx").get<double>();
    k.cy = entry.at("cy").get<double>();
    if (entry.contains("distortion")) {
      const std::vector<double> d = entry.at("distortion").get<std::vector<double>>();
      if (d.size() > 5) throw std::runtime_error("distortion has more than 5 coefficients");
      std::copy(d.begin(), d.end(), k.distortion.begin());
    }
    const std::vector<double> pose = entry.at("T_cam_world").get<std::vector<double>>();
    if (pose.size() != 16) {
      throw std::runtime_error("T_cam_world must have 16 numbers (row-major 4x4)");
    }
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        named.camera.T_cam_world.matrix()(r, c) = pose[static_cast<size_t>(4 * r + c)];
      }
    }
    if (const std::string problem = CheckCamera(named); !problem.empty()) {
      throw std::runtime_error(problem);
    }
    return named;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(e.what());
  }
}

void WriteCamerasJson(const fs::path& path, const std::vector<NamedCamera>& cameras) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const NamedCamera& named : cameras) list.push_back(CameraToJson(named));
  std::ofstream out = OpenForWriting(path);
  out << nlohmann::ordered_json{{"cameras", list}}.dump(1) << "\n";
  CheckWritten(out, path);
}

std::vector<NamedCamera> ReadCamerasJson(const fs::path& path) {
  std::ifstream in(path);
  if (!in) Fail(path, "", "cannot open");
  const nlohmann::json doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) Fail(path, "", "not valid JSON");
  const nlohmann::json* list = &doc;
  if (doc.is_object()) {
    if (!doc.contains("cameras")) Fail(path, "", "no \"cameras\" list");
    list = &doc["cameras"];
  }
  if (!list->is_array()) Fail(path, "", "\"cameras\" is not a list");
  std::vector<NamedCamera> cameras;
  for (size_t i = 0; i < list->size(); ++i) {
    try {
      cameras.push_back(CameraFromJson((*list)[i], fmt::format("view_{:04d}", i)));
    } catch (const std::runtime_error& e) {
      Fail(path, fmt::format(": camera {}", i), e.what());
    }
  }
  return cameras;
}

void WriteColmapText(const fs::path& dir, const std::vector<NamedCamera>& cameras) {
  fs::create_directories(dir);
  // COLMAP camera ids per distinct intrinsics, numbered in order of first use.
  std::vector<Intrinsics> distinct;
  std::vector<size_t> camera_of_view;
  for (const NamedCamera& named : cameras) {
    if (const std::string problem = CheckCamera(named); !problem.empty()) {
      throw std::invalid_argument(fmt::format("camera '{}': {}", named.name, problem));
    }
    const Intrinsics& k = named.camera.intrinsics;
    size_t id = 0;
    while (id < distinct.size() &&
           !(distinct[id].width == k.width && distinct[id].height == k.height &&
             distinct[id].fx == k.fx && distinct[id].fy == k.fy && distinct[id].cx == k.cx &&
             distinct[id].cy == k.cy && distinct[id].distortion == k.distortion)) {
      ++id;
    }
    if (id == distinct.size()) distinct.push_back(k);
    camera_of_view.push_back(id);
  }
  {
    std::ofstream out = OpenForWriting(dir / "cameras.txt");
    out << "# Camera list with one line of data per camera:\n"
           "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
        << "# Number of cameras: " << distinct.size() << "\n";
    for (size_t id = 0; id < distinct.size(); ++id) {
      const Intrinsics& k = distinct[id];
      const auto& d = k.distortion;
      if (d[4] == 0) {
        out << id + 1 << " OPENCV " << k.width << " " << k.height << " " << k.fx << " " << k.fy
            << " " << k.cx << " " << k.cy << " " << d[0] << " " << d[1] << " " << d[2] << " "
            << d[3] << "\n";
      } else {
        out << id + 1 << " FULL_OPENCV " << k.width << " " << k.height << " " << k.fx << " " << k.fy
            << " " << k.cx << " " << k.cy << " " << d[0] << " " << d[1] << " " << d[2] << " "
            << d[3] << " " << d[4] << " 0 0 0\n";
      }
    }
    CheckWritten(out, dir / "cameras.txt");
  }
  {
    std::ofstream out = OpenForWriting(dir / "images.txt");
    out << "# Image list with two lines of data per image:\n"
           "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
           "#   POINTS2D[] as (X, Y, POINT3D_ID)\n"
        << "# Number of images: " << cameras.size() << "\n";
    for (size_t i = 0; i < cameras.size(); ++i) {
      const Eigen::Isometry3d& pose = cameras[i].camera.T_cam_world;
      Eigen::Quaterniond q(pose.rotation());
      if (q.w() < 0) q.coeffs() = -q.coeffs();  // COLMAP writes qw >= 0
      const Eigen::Vector3d t = pose.translation();
      out << i + 1 << " " << q.w() << " " << q.x() << " " << q.y() << " " << q.z() << " " << t.x()
          << " " << t.y() << " " << t.z() << " " << camera_of_view[i] + 1 << " " << cameras[i].name
          << "\n\n";
    }
    CheckWritten(out, dir / "images.txt");
  }
  std::ofstream points = OpenForWriting(dir / "points3D.txt");
  points << "# 3D point list (empty: cameras are known, points come from our builder)\n";
  CheckWritten(points, dir / "points3D.txt");
}

namespace {

// Data lines of a COLMAP text file with their line numbers; comments skipped, blank lines kept
// (images.txt has an empty points line per image).
std::vector<std::pair<int, std::string>> ReadLines(const fs::path& path) {
  std::ifstream in(path);
  if (!in) Fail(path, "", "cannot open");
  std::vector<std::pair<int, std::string>> lines;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line[0] == '#') continue;
    lines.emplace_back(number, line);
  }
  return lines;
}

Intrinsics ParseColmapCamera(const fs::path& path, int line_number, std::istringstream& in,
                             const std::string& model) {
  Intrinsics k;
  const std::string where = fmt::format(":{}", line_number);
  if (!(in >> k.width >> k.height)) Fail(path, where, "bad image size");
  std::vector<double> p;
  for (double value; in >> value;) p.push_back(value);
  auto need = [&](size_t n) {
    if (p.size() != n) {
      Fail(path, where, fmt::format("model {} needs {} parameters, found {}", model, n, p.size()));
    }
  };
  if (model == "PINHOLE") {
    need(4);
    k.fx = p[0], k.fy = p[1], k.cx = p[2], k.cy = p[3];
  } else if (model == "SIMPLE_PINHOLE") {
    need(3);
    k.fx = k.fy = p[0], k.cx = p[1], k.cy = p[2];
  } else if (model == "SIMPLE_RADIAL" || model == "RADIAL") {
    need(model == "RADIAL" ? 5 : 4);
    k.fx = k.fy = p[0], k.cx = p[1], k.cy = p[2];
    k.distortion[0] = p[3];
    if (model == "RADIAL") k.distortion[1] = p[4];
  } else if (model == "OPENCV" || model == "FULL_OPENCV") {
    need(model == "OPENCV" ? 8 : 12);
    k.fx = p[0], k.fy = p[1], k.cx = p[2], k.cy = p[3];
    for (size_t i = 0; i < 4; ++i) k.distortion[i] = p[4 + i];
    if (model == "FULL_OPENCV") {
      k.distortion[4] = p[8];
      if (p[9] != 0 || p[10] != 0 || p[11] != 0) {
        Fail(path, where, "FULL_OPENCV with k4..k6 (rational model) is not supported");
      }
    }
  } else {
    Fail(path, where,
         "camera model " + model +
             " is not supported (use PINHOLE, SIMPLE_PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV or "
             "FULL_OPENCV)");
  }
  if (const std::string problem = k.Validate(); !problem.empty()) Fail(path, where, problem);
  return k;
}

}  // namespace

std::vector<NamedCamera> ReadColmapText(const fs::path& dir) {
  const fs::path cameras_file = dir / "cameras.txt";
  std::map<int, Intrinsics> intrinsics;
  for (const auto& [number, line] : ReadLines(cameras_file)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream in(line);
    int id = 0;
    std::string model;
    if (!(in >> id >> model)) Fail(cameras_file, fmt::format(":{}", number), "bad camera line");
    intrinsics[id] = ParseColmapCamera(cameras_file, number, in, model);
  }
  const fs::path images_file = dir / "images.txt";
  const auto lines = ReadLines(images_file);
  std::vector<NamedCamera> cameras;
  for (size_t i = 0; i < lines.size(); ++i) {
    const auto& [number, line] = lines[i];
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream in(line);
    int image_id = 0, camera_id = 0;
    double qw, qx, qy, qz, tx, ty, tz;
    NamedCamera named;
    if (!(in >> image_id >> qw >> qx >> qy >> qz >> tx >> ty >> tz >> camera_id >> named.name)) {
      Fail(images_file, fmt::format(":{}", number), "bad image line");
    }
    const auto it = intrinsics.find(camera_id);
    if (it == intrinsics.end()) {
      Fail(images_file, fmt::format(":{}", number),
           fmt::format("camera {} is not in cameras.txt", camera_id));
    }
    const Eigen::Quaterniond q(qw, qx, qy, qz);
    if (!(std::abs(q.norm() - 1) < 1e-3)) {
      Fail(images_file, fmt::format(":{}", number), "quaternion is not unit length");
    }
    named.camera.intrinsics = it->second;
    named.camera.T_cam_world.linear() = q.normalized().toRotationMatrix();
    named.camera.T_cam_world.translation() = Eigen::Vector3d(tx, ty, tz);
    cameras.push_back(std::move(named));
    ++i;  // the POINTS2D line that follows every image line
  }
  return cameras;
}

}  // namespace avc::camera
