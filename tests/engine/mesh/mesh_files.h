// Mesh files written by the tests: OBJ with the positions given, and glTF 2.0 (one embedded
// buffer) whose mesh sits under a chain of nodes, each with a TRS or a matrix transform.
#pragma once
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "platon/stage/mesh.h"

namespace platon::testfiles {

// One node of the chain, root first: either a matrix (column-major, as glTF writes it) or TRS.
struct Node {
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d scale = Eigen::Vector3d::Ones(), translation = Eigen::Vector3d::Zero();
  bool asMatrix = false;

  Eigen::Affine3d transform() const { return Eigen::Translation3d(translation) * rotation * Eigen::Scaling(scale); }
};

inline void writeObj(const stage::MeshData& m, const std::string& path) {
  std::ofstream out(path);
  char line[128];
  for (const auto& p : m.positions) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
    out << line;
  }
  for (const auto& t : m.triangles) out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
}

inline std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t n = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) n |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) n |= uint32_t(uint8_t(bytes[i + 2]));
    out += digits[(n >> 18) & 63];
    out += digits[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[n & 63] : '=';
  }
  return out;
}

inline std::string numbers(const double* v, int n) {
  std::ostringstream s;
  s.precision(17);
  for (int i = 0; i < n; ++i) s << (i ? "," : "") << v[i];
  return "[" + s.str() + "]";
}

inline std::string nodeJson(const Node& node, int index, bool last) {
  std::string json = "{";
  if (node.asMatrix) {
    const Eigen::Matrix4d m = node.transform().matrix();
    double columns[16];
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) columns[4 * c + r] = m(r, c);
    json += "\"matrix\":" + numbers(columns, 16);
  } else {
    const double r[4] = {node.rotation.x(), node.rotation.y(), node.rotation.z(), node.rotation.w()};
    json += "\"rotation\":" + numbers(r, 4) + ",\"scale\":" + numbers(node.scale.data(), 3) +
            ",\"translation\":" + numbers(node.translation.data(), 3);
  }
  json += last ? ",\"mesh\":0" : ",\"children\":[" + std::to_string(index + 1) + "]";
  return json + "}";
}

// The mesh (positions stored as 32-bit floats, as glTF does) under the chain of nodes. Its buffer
// is in the file, or, with `uri`, named by it (its bytes left in *bufferBytes for the caller to put).
inline void writeGltf(const stage::MeshData& m, const std::vector<Node>& chain, const std::string& path,
                      const std::string& uri = "", std::string* bufferBytes = nullptr) {
  std::string buffer;
  Eigen::Vector3d lo = m.positions[0], hi = m.positions[0];
  for (const auto& p : m.positions) {
    lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    for (int c = 0; c < 3; ++c) {
      const float f = static_cast<float>(p[c]);
      buffer.append(reinterpret_cast<const char*>(&f), 4);
    }
  }
  const size_t positionBytes = buffer.size();
  for (const auto& t : m.triangles)
    for (const int v : t) {
      const auto u = static_cast<uint32_t>(v);
      buffer.append(reinterpret_cast<const char*>(&u), 4);
    }
  const std::vector<Node> nodes = chain.empty() ? std::vector<Node>{Node{}} : chain;
  std::string nodeList;
  for (size_t i = 0; i < nodes.size(); ++i)
    nodeList += (i ? "," : "") + nodeJson(nodes[i], int(i), i + 1 == nodes.size());
  const double low[3] = {double(float(lo.x())), double(float(lo.y())), double(float(lo.z()))};
  const double high[3] = {double(float(hi.x())), double(float(hi.y())), double(float(hi.z()))};
  std::ofstream(path) << "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":["
                      << nodeList
                      << "],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
                      << "\"buffers\":[{\"byteLength\":" << buffer.size() << ",\"uri\":\""
                      << (uri.empty() ? "data:application/octet-stream;base64," + base64(buffer) : uri) << "\"}],"
                      << "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":" << positionBytes
                      << "},{\"buffer\":0,\"byteOffset\":" << positionBytes
                      << ",\"byteLength\":" << buffer.size() - positionBytes
                      << "}],\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":" << m.positions.size()
                      << ",\"type\":\"VEC3\",\"min\":" << numbers(low, 3) << ",\"max\":" << numbers(high, 3)
                      << "},{\"bufferView\":1,\"componentType\":5125,\"count\":" << 3 * m.triangles.size()
                      << ",\"type\":\"SCALAR\"}]}\n";
  if (bufferBytes) *bufferBytes = buffer;
}

// The mesh with the chain's transform written into its points (what a modeller's "apply
// transforms" does), in double precision.
inline stage::MeshData baked(stage::MeshData m, const std::vector<Node>& chain) {
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  for (const Node& n : chain) t = t * n.transform();
  for (auto& p : m.positions) p = t * p;
  if (t.linear().determinant() < 0)
    for (auto& tri : m.triangles) std::swap(tri[1], tri[2]);
  return m;
}

}  // namespace platon::testfiles
