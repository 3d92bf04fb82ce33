#include "remote_protocol.hpp"

#include <nlohmann/json.hpp>

#include <sstream>

#include "plexus/base/input_error.hpp"

namespace plexus::cli {

std::string RemoteRequest::to_line() const {
  const nlohmann::json j = {{"host", host},
                            {"scenario_text", scenario_text},
                            {"scenario_origin", scenario_origin},
                            {"sets", sets},
                            {"vendors", vendors},
                            {"externals", externals},
                            {"dds", dds},
                            {"qos_file", qos_file},
                            {"out", out},
                            {"domain", domain},
                            {"timeout", timeout},
                            {"clock_injection_ns", clock_injection_ns}};
  return "request " + j.dump();
}

RemoteRequest RemoteRequest::from_line(const std::string& line, const std::string& where) {
  if (line.rfind("request ", 0) != 0)
    throw InputError(where + ": expected the launcher's request, got '" + line.substr(0, 40) + "'");
  try {
    const auto j = nlohmann::json::parse(line.substr(8));
    RemoteRequest r;
    r.host = j.at("host").get<std::string>();
    r.scenario_text = j.at("scenario_text").get<std::string>();
    r.scenario_origin = j.at("scenario_origin").get<std::string>();
    r.sets = j.at("sets").get<std::vector<std::string>>();
    r.vendors = j.at("vendors").get<std::vector<std::string>>();
    r.externals = j.at("externals").get<std::vector<std::string>>();
    r.dds = j.at("dds").get<std::string>();
    r.qos_file = j.at("qos_file").get<std::string>();
    r.out = j.at("out").get<std::string>();
    r.domain = j.at("domain").get<int>();
    r.timeout = j.at("timeout").get<double>();
    r.clock_injection_ns = j.at("clock_injection_ns").get<int64_t>();
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where + ": malformed launcher request (" + e.what() + ")");
  }
}

std::string RemoteReady::to_line() const {
  const nlohmann::json j = {{"digest", digest},
                            {"qos_file", qos_file},
                            {"address", address},
                            {"address_found", address_found},
                            {"processes", processes}};
  return "ready " + j.dump();
}

bool RemoteReady::from_line(const std::string& line, RemoteReady& out) {
  if (line.rfind("ready ", 0) != 0) return false;
  try {
    const auto j = nlohmann::json::parse(line.substr(6));
    out.digest = j.at("digest").get<std::string>();
    out.qos_file = j.at("qos_file").get<std::string>();
    out.address = j.at("address").get<std::string>();
    out.address_found = j.at("address_found").get<bool>();
    out.processes = j.at("processes").get<int>();
    return true;
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

std::string hello_line(const std::string& version) {
  return std::string(kRemoteHello) + " " + std::to_string(kRemoteProtocol) + " " + version;
}

bool parse_hello(const std::string& line, int& protocol, std::string& version) {
  std::istringstream in(line);
  std::string word;
  if (!(in >> word) || word != kRemoteHello) return false;
  if (!(in >> protocol >> version)) return false;
  return true;
}

}  // namespace plexus::cli
