// watkins_gl_bench: Mesa's software GL (OSMesa, llvmpipe) on the same screen triangles as the
// bit-exact model, for scripts/bench's side-by-side figures. The scene's screen polygons (quads
// split (v0,v1,v2), (v0,v2,v3), as the model's `triangles` option does) are drawn with GL_LESS
// depth, positions given directly in normalized device coordinates so a pixel is a pixel (and
// every attribute is interpolated linearly in the screen, as the model's); best time over repeated
// frames (glFinish each), a benchmark, not a test. Fragments per second use the model's fragment
// count for the same scene (GL does not count its own; its top-left fill rule covers the same
// pixels up to edges that fall exactly on pixel centres).
//   Gouraud: smooth-shaded vertex colours (the fixed-function pipeline).
//   Phong: a GLSL fragment shader evaluating Phong's eq. (3) per pixel, as the model's
//   normalizer and phong_shader do, on the same vertex normals, the frame's quantized light, eye
//   and materials (Cp, d clamped to 1, W, n): S = Cp [max(N.L, 0)(1 - d) + d] + W cos(s)^n with
//   cos(s) = 2 (N.L)(N.E) - L.E, the specular term only where N.L > 0 and cos(s) > 0.
// LP_NUM_THREADS=0 (the default, --threads 0) draws everything on the calling thread, a per-core
// figure beside the single-threaded model; --threads N gives llvmpipe N rasterizer threads.
// The GL image is compared with the model's over the pixels both cover, in 8-bit levels.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "grid_scene.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "watkins_top.hpp"

namespace {

// Eq. (3) per pixel; the interpolated normal is normalized here, as the model's normalizer does.
constexpr const char* kPhongVertex = R"(#version 120
attribute vec3 position;
attribute vec3 normal;
attribute vec3 cp;
attribute vec3 dwn;
varying vec3 v_normal;
varying vec3 v_cp;
varying vec3 v_dwn;
void main() {
  v_normal = normal;
  v_cp = cp;
  v_dwn = dwn;
  gl_Position = vec4(position, 1.0);
}
)";
constexpr const char* kPhongFragment = R"(#version 120
uniform vec3 light;
uniform vec3 eye;
varying vec3 v_normal;
varying vec3 v_cp;
varying vec3 v_dwn;
void main() {
  vec3 n = normalize(v_normal);
  float cos_i = dot(n, light);
  float cos_s = 2.0 * cos_i * dot(n, eye) - dot(light, eye);
  float d = min(v_dwn.x, 1.0);
  float diffuse = max(cos_i, 0.0) * (1.0 - d) + d;
  float specular = (cos_i > 0.0 && cos_s > 0.0) ? v_dwn.y * pow(min(cos_s, 1.0), v_dwn.z) : 0.0;
  gl_FragColor = vec4(v_cp * diffuse + vec3(specular), 1.0);
}
)";

GLuint compile(GLenum kind, const char* text) {
  const GLuint s = glCreateShader(kind);
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("GLSL: ") + log);
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"watkins_gl_bench: Mesa llvmpipe (OSMesa) on the model's screen triangles"};
  std::string scene_path, shading;
  int grid = 0, threads = 0;
  double budget = 1.0;
  CLI::Option* scene_opt = app.add_option("scene", scene_path, "scene file (default: the embedded default scene)");
  app.add_option("--grid", grid, "instead of a scene: a 512x512 screen of 2*N*N triangles covering each pixel once")
      ->check(CLI::Range(1, 256))
      ->excludes(scene_opt);
  app.add_option("--shading", shading, "gouraud or phong (default: the scene's)")
      ->check(CLI::IsMember({"gouraud", "phong"}));
  app.add_option("--threads", threads, "llvmpipe's rasterizer threads (LP_NUM_THREADS; 0: the calling thread only)")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  app.add_option("--seconds", budget, "time budget")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  // Read when the context is created.
  setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);
  try {
    using namespace watkins;
    BuildOptions opt;
    if (!shading.empty()) opt.shading = shading == "phong" ? ShadingMode::Phong : ShadingMode::Gouraud;
    const BuiltScene scene = grid > 0 ? grid_scene(512, grid) : load_scene_or_default(scene_path, opt);
    const bool phong = scene.shading == ShadingMode::Phong;
    Config cfg;
    cfg.max_active_edges = 1 << 20;
    cfg.max_width = std::max(cfg.max_width, scene.width);
    const PreparedScene prepared = prepare(scene, cfg);
    WatkinsTop model(cfg);
    const Image model_image = model.render(prepared);
    const long long fragments = model.stats().fragments;

    // Per vertex: x, y, z (NDC); Gouraud r, g, b; Phong the normal, Cp, and (d, W, n) of its
    // polygon's material from the frame's quantized table. Three vertices per triangle.
    std::vector<float> xyz, rgb, normal, cp, dwn;
    auto put = [&](const ScreenPolygon& p, const ScreenVertex& v) {
      xyz.push_back(float(2.0 * v.x / scene.width - 1.0));
      xyz.push_back(float(1.0 - 2.0 * v.y / scene.height));  // scan lines run down
      xyz.push_back(float(2.0 * v.depth - 1.0));               // window depth = depth
      for (int c = 0; c < 3; ++c) rgb.push_back(float(v.rgb[c] / 255.0));
      if (!phong) return;
      const QuantizedMaterial& m = prepared.materials.at(static_cast<std::size_t>(p.material));
      for (int c = 0; c < 3; ++c) normal.push_back(float(v.normal[c])), cp.push_back(float(m.cp[c] / 255.0));
      dwn.push_back(float(m.d / 256.0)), dwn.push_back(float(m.w / 256.0)), dwn.push_back(float(m.shininess));
    };
    for (const ScreenPolygon& p : scene.polygons)
      for (std::size_t k = 1; k + 1 < p.v.size(); ++k) put(p, p.v[0]), put(p, p.v[k]), put(p, p.v[k + 1]);
    const auto vertices = static_cast<GLsizei>(xyz.size() / 3);

    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!ctx) throw std::runtime_error("OSMesaCreateContextExt failed");
    std::vector<unsigned char> buffer(std::size_t(scene.width) * scene.height * 4);
    if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, scene.width, scene.height))
      throw std::runtime_error("OSMesaMakeCurrent failed");
    glViewport(0, 0, scene.width, scene.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    // Alpha 0 where nothing is drawn: GL's coverage, for the image comparison.
    glClearColor(float(scene.background[0] / 255), float(scene.background[1] / 255), float(scene.background[2] / 255), 0);
    if (phong) {
      const GLuint program = glCreateProgram();
      glAttachShader(program, compile(GL_VERTEX_SHADER, kPhongVertex));
      glAttachShader(program, compile(GL_FRAGMENT_SHADER, kPhongFragment));
      glBindAttribLocation(program, 0, "position");
      glBindAttribLocation(program, 1, "normal");
      glBindAttribLocation(program, 2, "cp");
      glBindAttribLocation(program, 3, "dwn");
      glLinkProgram(program);
      GLint ok = 0;
      glGetProgramiv(program, GL_LINK_STATUS, &ok);
      if (!ok) throw std::runtime_error("GLSL program does not link");
      glUseProgram(program);
      const double unit = 1 << fmt::UnitFracBits;  // the frame's light and eye, Q2.14
      glUniform3f(glGetUniformLocation(program, "light"), float(prepared.light[0] / unit),
                  float(prepared.light[1] / unit), float(prepared.light[2] / unit));
      glUniform3f(glGetUniformLocation(program, "eye"), float(prepared.eye[0] / unit), float(prepared.eye[1] / unit),
                  float(prepared.eye[2] / unit));
      const std::vector<float>* attrib[] = {&xyz, &normal, &cp, &dwn};
      for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, 3, GL_FLOAT, GL_FALSE, 0, attrib[a]->data());
      }
    } else {
      glShadeModel(GL_SMOOTH);
      glEnableClientState(GL_VERTEX_ARRAY);
      glEnableClientState(GL_COLOR_ARRAY);
      glVertexPointer(3, GL_FLOAT, 0, xyz.data());
      glColorPointer(3, GL_FLOAT, 0, rgb.data());
    }
    auto frame = [&] {
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glDrawArrays(GL_TRIANGLES, 0, vertices);
      glFinish();
    };
    frame();  // compiles llvmpipe's shaders outside the timing
    using Clock = std::chrono::steady_clock;
    double best = 1e300, spent = 0;
    for (int runs = 0; spent < budget || runs < 3; ++runs) {
      const auto t0 = Clock::now();
      frame();
      const double s = std::chrono::duration<double>(Clock::now() - t0).count();
      best = std::min(best, s), spent += s;
    }
    // GL's rows run up the screen; the model's down.
    long long both = 0, over_one = 0, sum = 0, coverage_differs = 0;
    int max_abs = 0;
    for (int y = 0; y < scene.height; ++y)
      for (int x = 0; x < scene.width; ++x) {
        const unsigned char* g = &buffer[(std::size_t(scene.height - 1 - y) * scene.width + x) * 4];
        const bool gl_covered = g[3] != 0, model_covered = model_image.is_covered(x, y);
        if (gl_covered != model_covered) ++coverage_differs;
        if (!gl_covered || !model_covered) continue;
        ++both;
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
          const int d = std::abs(int(g[c]) - int(model_image.at(x, y)[c]));
          worst = std::max(worst, d), sum += d;
        }
        max_abs = std::max(max_abs, worst), over_one += worst > 1;
      }
    std::printf("scene               %s (%dx%d, %d triangles, %lld fragments in the model)\n", scene.name.c_str(),
                scene.width, scene.height, vertices / 3, fragments);
    std::printf("mesa gl             %.3f ms/frame  %.2f M fragments/s  (%s, %s, LP_NUM_THREADS=%d%s)\n",
                best * 1e3, fragments / best / 1e6, reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                phong ? "GLSL Phong eq. (3) per pixel" : "smooth shading", threads,
                threads == 0 ? ": all on the calling thread" : "");
    std::printf("gl against model    max |d| %d levels, mean |d| %.4f levels, %lld pixels > 1 level (of %lld both "
                "cover); %lld pixels covered by one only\n",
                max_abs, both ? double(sum) / (3.0 * both) : 0.0, over_one, both, coverage_differs);
    OSMesaDestroyContext(ctx);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "watkins_gl_bench: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
