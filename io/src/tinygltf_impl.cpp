// The tinygltf implementation, compiled here rather than linked from Debian's libtinygltf so that
// its options are ours (set for the whole target in io/CMakeLists.txt, since they change the
// declarations every includer sees): no image decoding or writing, no external images.
// KHR_draco_mesh_compression is decoded in read_gltf.cpp, not by tinygltf's TINYGLTF_ENABLE_DRACO
// path: in tinygltf 2.7.0 that path indexes bufferViews, buffers and accessors without bounds checks
// and dereferences a missing Draco attribute, so a hostile file would crash the host process.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
