// watkins_gl_bench: Mesa's software GL (OSMesa, llvmpipe with LP_NUM_THREADS=0: one thread) on
// the same screen triangles as the bit-exact model, for scripts/bench's side-by-side figures. The scene's screen
// polygons (quads split (v0,v1,v2), (v0,v2,v3), as the model's `triangles` option does) are drawn
// with smooth shading and GL_LESS depth, positions given directly in normalized device
// coordinates so a pixel is a pixel; best time over repeated frames (glFinish each), a benchmark,
// not a test. Fragments per second use the model's fragment count for the same scene (GL does not
// count its own; its top-left fill rule covers the same pixels up to edges that fall exactly on
// pixel centres).
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "grid_scene.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "watkins_top.hpp"

int main(int argc, char** argv) {
  CLI::App app{"watkins_gl_bench: Mesa llvmpipe (OSMesa, one thread) on the model's screen triangles"};
  std::string scene_path;
  int grid = 0;
  double budget = 1.0;
  CLI::Option* scene_opt = app.add_option("scene", scene_path, "scene file (default: the embedded default scene)");
  app.add_option("--grid", grid, "instead of a scene: a 512x512 screen of 2*N*N triangles covering each pixel once")
      ->check(CLI::Range(1, 256))
      ->excludes(scene_opt);
  app.add_option("--seconds", budget, "time budget")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  // No rasterizer threads: llvmpipe runs everything on the calling thread, a per-core figure
  // beside the single-threaded model (read when the context is created).
  setenv("LP_NUM_THREADS", "0", 1);
  try {
    using namespace watkins;
    const BuiltScene scene = grid > 0 ? grid_scene(512, grid) : load_scene_or_default(scene_path);
    if (scene.shading != ShadingMode::Gouraud) throw std::runtime_error("the GL comparison draws Gouraud shades");
    Config cfg;
    cfg.max_active_edges = 1 << 20;
    cfg.max_width = std::max(cfg.max_width, scene.width);
    WatkinsTop model(cfg);
    model.render(prepare(scene, cfg));
    const long long fragments = model.stats().fragments;

    // Interleaved x, y, z (NDC) and r, g, b per vertex, three vertices per triangle.
    std::vector<float> xyz, rgb;
    auto put = [&](const ScreenVertex& v) {
      xyz.push_back(float(2.0 * v.x / scene.width - 1.0));
      xyz.push_back(float(1.0 - 2.0 * v.y / scene.height));  // scan lines run down
      xyz.push_back(float(2.0 * v.depth - 1.0));               // window depth = depth
      for (int c = 0; c < 3; ++c) rgb.push_back(float(v.rgb[c] / 255.0));
    };
    for (const ScreenPolygon& p : scene.polygons)
      for (std::size_t k = 1; k + 1 < p.v.size(); ++k) put(p.v[0]), put(p.v[k]), put(p.v[k + 1]);
    const auto vertices = static_cast<GLsizei>(xyz.size() / 3);

    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!ctx) throw std::runtime_error("OSMesaCreateContextExt failed");
    std::vector<unsigned char> buffer(std::size_t(scene.width) * scene.height * 4);
    if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, scene.width, scene.height))
      throw std::runtime_error("OSMesaMakeCurrent failed");
    glViewport(0, 0, scene.width, scene.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glShadeModel(GL_SMOOTH);
    glClearColor(float(scene.background[0] / 255), float(scene.background[1] / 255), float(scene.background[2] / 255), 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, xyz.data());
    glColorPointer(3, GL_FLOAT, 0, rgb.data());
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
    std::printf("scene               %s (%dx%d, %d triangles, %lld fragments in the model)\n", scene.name.c_str(),
                scene.width, scene.height, vertices / 3, fragments);
    std::printf("mesa gl             %.3f ms/frame  %.2f M fragments/s  (%s, LP_NUM_THREADS=0: all on the calling thread)\n", best * 1e3,
                fragments / best / 1e6, reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
    OSMesaDestroyContext(ctx);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "watkins_gl_bench: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
