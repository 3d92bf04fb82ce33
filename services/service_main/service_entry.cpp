// main() of one service executable: PLEXUS_SERVICE_NAME is its name (CMakeLists.txt).
#include "services/service_main/service_main.hpp"

int main(int argc, char** argv) { return plexus::service::run_service(argc, argv, PLEXUS_SERVICE_NAME); }
