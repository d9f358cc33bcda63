#include "gl_timer.h"

namespace vct::gl {

// GL_TIMESTAMP pairs rather than GL_TIME_ELAPSED: on llvmpipe (Mesa 22.3) a TIME_ELAPSED query
// around depth-only rendering into a layer of a texture array reported nonsense (~45 minutes);
// timestamp differences measure the same GPU interval and behaved on every pass.
void GpuTimers::begin(const std::string& stage) {
  if (open_) end();
  GLuint q[2] = {0, 0};
  glGenQueries(2, q);
  glQueryCounter(q[0], GL_TIMESTAMP);
  queries_.push_back({stage, q[0], q[1]});
  open_ = true;
}

void GpuTimers::end() {
  if (!open_) return;
  // llvmpipe bins draws and rasterizes them at flush time, so without a finish a stage's work is
  // billed to whichever later stage flushes. One sync per stage is cheap for a validation tool.
  // A GPU writes the timestamp when the work before it is done, with no finish (GL 4.5 §4.3).
  if (finish_) glFinish();
  glQueryCounter(queries_.back().end, GL_TIMESTAMP);
  open_ = false;
}

std::map<std::string, double> GpuTimers::collect() {
  end();
  std::map<std::string, double> ms;
  for (const auto& q : queries_) {
    GLuint64 t0 = 0, t1 = 0;
    glGetQueryObjectui64v(q.begin, GL_QUERY_RESULT, &t0);
    glGetQueryObjectui64v(q.end, GL_QUERY_RESULT, &t1);
    ms[q.stage] += t1 > t0 ? double(t1 - t0) * 1e-6 : 0.0;
    const GLuint ids[2] = {q.begin, q.end};
    glDeleteQueries(2, ids);
  }
  queries_.clear();
  return ms;
}

}  // namespace vct::gl
