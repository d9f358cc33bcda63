#include "renderdoc_reader.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "interrupt.h"
#include "io/bounded_json.h"
#include "validate_run.h"

namespace vct::app {
namespace fs = std::filesystem;
namespace {

// rdc_read.py's exit codes (its docstring): 2 bad input, 3 environment.
constexpr int kScriptBadInput = 2, kScriptNoEnvironment = 3;

std::string default_python() {
  if (const char* env = std::getenv("VCT_RENDERDOC_PYTHON")) return env;
  return "/usr/bin/python3";
}

std::string default_script() {
  const std::string root = find_source_root();
  const fs::path script = fs::path(root) / "tools" / "import_capture" / "rdc_read.py";
  if (root.empty() || !fs::exists(script))
    throw EnvironmentError("tools/import_capture/rdc_read.py not found (set VCT_SOURCE_DIR to the source tree)");
  return script.string();
}

nlohmann::json request_of(const std::vector<cmp::CaptureStage>& stages) {
  nlohmann::json list = nlohmann::json::array();
  for (const cmp::CaptureStage& s : stages)
    list.push_back({{"name", s.name}, {"resource", s.resource}, {"event", s.event}, {"mip", s.mip}, {"slice", s.slice}, {"sample", s.sample}});
  return {{"stages", list}};
}

std::string last_line(const std::string& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last.empty() ? "no message" : last;
}

cmp::CapturedTexture texture_of(const nlohmann::json& e, const fs::path& file) {
  cmp::CapturedTexture t;
  t.width = e.at("width").get<int>();
  t.height = e.at("height").get<int>();
  t.depth = e.at("depth").get<int>();
  t.channels = e.at("channels").get<int>();
  t.format = e.at("format").get<std::string>();
  const uintmax_t bytes = fs::file_size(file);
  t.data.resize(size_t(bytes / sizeof(float)));
  std::ifstream in(file, std::ios::binary);
  in.read(reinterpret_cast<char*>(t.data.data()), std::streamsize(t.data.size() * sizeof(float)));
  return t;
}

}  // namespace

RenderDocReader::RenderDocReader(std::string python, std::string script)
    : python_(python.empty() ? default_python() : std::move(python)), script_(std::move(script)) {}

std::vector<cmp::CapturedTexture> RenderDocReader::read(const std::string& capture, const std::vector<cmp::CaptureStage>& stages) {
  if (!fs::is_regular_file(capture)) throw InputError(capture, "no such capture file");
  if (!fs::exists(python_)) throw EnvironmentError(python_ + " not found (python3-renderdoc replays under the system python3)");
  const std::string script = script_.empty() ? default_script() : script_;
  const fs::path work = fs::temp_directory_path() / ("vct-rdc-" + std::to_string(getpid()));
  fs::remove_all(work);
  fs::create_directories(work);
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code ignored;
      fs::remove_all(dir, ignored);
    }
  } cleanup{work};
  std::ofstream(work / "request.json") << request_of(stages).dump();
  const std::string log = (work / "stderr.txt").string();
  const int status = run_child(shell_quote(python_) + " " + shell_quote(script) + " " + shell_quote(fs::absolute(capture).string()) +
                               " " + shell_quote((work / "request.json").string()) + " " + shell_quote(work.string()) +
                               " > /dev/null 2> " + shell_quote(log));
  const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (rc == kScriptBadInput) throw InputError(capture, last_line(log));
  if (rc != 0) throw EnvironmentError("RenderDoc replay: " + last_line(log) + (rc == kScriptNoEnvironment ? "" : " (exit " + std::to_string(rc) + ")"));
  const nlohmann::json index = read_bounded_json_file((work / "index.json").string(), "rdc_read index");
  std::vector<cmp::CapturedTexture> out;
  for (size_t i = 0; i < index.size(); ++i) out.push_back(texture_of(index[i], work / (std::to_string(i) + ".f32")));
  return out;
}

}  // namespace vct::app
