# Tests of the QoS/latency tools (issue 9): plexus topic, record, replay, latency. Functional
# only (no timing thresholds), on both vendors. DDS domains 180-229 are this file's.
add_executable(topic_peer ${CMAKE_CURRENT_LIST_DIR}/topic_peer.cpp)
target_link_libraries(topic_peer PRIVATE plexus_runtime CLI11::CLI11)
plexus_warnings(topic_peer)

set(TOOLS_DIR ${CMAKE_CURRENT_LIST_DIR})
set(PLEXUS_CLI $<TARGET_FILE:plexus>)
set(TOPIC_PEER $<TARGET_FILE:topic_peer>)
set(BIN_DIR $<TARGET_FILE_DIR:plexus>)
set(TOOLS_DOMAIN 180)
foreach(v fast cyclone)
  set(D ${TOOLS_DOMAIN})
  add_test(NAME tools.topic_list_${v}
           COMMAND ${TOOLS_DIR}/with_peers.sh "tools/pose +plexus::msg::Pose2D +1 writer, 0 readers"
                   "${TOPIC_PEER} pub --dds ${v} --domain ${D} --topic tools/pose --duration 20" --
                   ${PLEXUS_CLI} topic list --dds ${v} --domain ${D} --wait 5)
  math(EXPR D "${D} + 1")
  add_test(NAME tools.topic_echo_csv_${v}
           COMMAND ${TOOLS_DIR}/with_peers.sh "receive_time_ns,header.seq_num,header.data_time_ns,header.origin_time_ns,header.publish_time_ns,x,y,theta"
                   "${TOPIC_PEER} pub --dds ${v} --domain ${D} --topic tools/pose --duration 20" --
                   ${PLEXUS_CLI} topic echo tools/pose --dds ${v} --domain ${D} --count 3 --csv --wait 10)
  math(EXPR D "${D} + 1")
  add_test(NAME tools.topic_echo_json_${v}
           COMMAND ${TOOLS_DIR}/with_peers.sh "\"theta\": 0.5"
                   "${TOPIC_PEER} pub --dds ${v} --domain ${D} --topic tools/pose --duration 20" --
                   ${PLEXUS_CLI} topic echo tools/pose --dds ${v} --domain ${D} --count 2 --wait 10)
  math(EXPR D "${D} + 1")
  add_test(NAME tools.topic_hz_${v}
           COMMAND ${TOOLS_DIR}/with_peers.sh "\"samples\":[1-9][0-9]*,\"rate_hz\""
                   "${TOPIC_PEER} pub --dds ${v} --domain ${D} --topic tools/pose --rate 100 --duration 20" --
                   ${PLEXUS_CLI} topic hz tools/pose --dds ${v} --domain ${D} --duration 2 --json --wait 10)
  math(EXPR D "${D} + 1")
  # A best-effort writer and a reliable reader: info names RELIABILITY.
  add_test(NAME tools.topic_info_incompatible_${v}
           COMMAND ${TOOLS_DIR}/with_peers.sh "INCOMPATIBLE RELIABILITY \\(writer offers best_effort, reader requests reliable\\)"
                   "${TOPIC_PEER} pub --dds ${v} --domain ${D} --topic tools/mismatch --profile sensor --duration 20"
                   "${TOPIC_PEER} sub --dds ${v} --domain ${D} --topic tools/mismatch --profile sensor_reliable --duration 20" --
                   ${PLEXUS_CLI} topic info tools/mismatch --dds ${v} --domain ${D} --wait 5)
  math(EXPR D "${D} + 1")
  add_test(NAME tools.topic_info_matched_${v}
           COMMAND ${TOOLS_DIR}/with_peers.sh "topic_peer_pub -> topic_peer_sub: matched"
                   "${TOPIC_PEER} pub --dds ${v} --domain ${D} --topic tools/ok --profile sensor_reliable --duration 20"
                   "${TOPIC_PEER} sub --dds ${v} --domain ${D} --topic tools/ok --profile sensor --duration 20" --
                   ${PLEXUS_CLI} topic info tools/ok --dds ${v} --domain ${D} --wait 5)
  math(EXPR D "${D} + 1")
  add_test(NAME tools.record_replay_${v}
           COMMAND ${TOOLS_DIR}/record_replay.sh ${BIN_DIR} ${v} ${D} ${CMAKE_BINARY_DIR}/test-runs/tools/record_replay_${v})
  math(EXPR D "${D} + 1")
  # Exit 0 (plexus lost no round trip), every one of plexus's 200 round trips back, real
  # statistics, and the vendor's own tool measured beside it.
  add_test(NAME tools.latency_pingpong_${v}
           COMMAND ${CMAKE_COMMAND}
                   "-DCOMMAND=${PLEXUS_CLI}|latency|pingpong|--dds|${v}|--count|200|--rate|200|--size|64|--domain|${D}|--json"
                   "-DCHECKS=plexus.received == 200;plexus.rtt_p50_us > 0;plexus.rtt_max_us >= 0;vendor.received > 0;vendor.rtt_p50_us > 0;ratio.mean > 0"
                   -P ${PROJECT_SOURCE_DIR}/tests/scripts/json_checks.cmake)
  math(EXPR D "${D} + 2")
  add_test(NAME tools.latency_pipeline_${v}
           COMMAND ${TOOLS_DIR}/pipeline_demo.sh ${BIN_DIR} ${v} ${D} ${CMAKE_BINARY_DIR}/test-runs/tools/pipeline_${v})
  math(EXPR D "${D} + 1")
  set_tests_properties(tools.topic_list_${v} tools.topic_echo_csv_${v} tools.topic_echo_json_${v} tools.topic_hz_${v}
                       tools.topic_info_incompatible_${v} tools.topic_info_matched_${v} tools.record_replay_${v}
                       tools.latency_pingpong_${v} tools.latency_pipeline_${v}
                       PROPERTIES LABELS "tools;multiprocess" TIMEOUT 120)
  set(TOOLS_DOMAIN ${D})
endforeach()

# LatencyProbe (the variable-size type) across vendors, both directions, 4 KiB payload.
foreach(variant "fast_to_cyclone;fast;cyclone;210" "cyclone_to_fast;cyclone;fast;212")
  list(POP_FRONT variant name dds peer domain)
  add_test(NAME tools.latency_probe_${name}
           COMMAND ${CMAKE_COMMAND}
                   "-DCOMMAND=${PLEXUS_CLI}|latency|pingpong|--dds|${dds}|--peer-dds|${peer}|--size|4096|--count|100|--rate|100|--domain|${domain}|--no-baseline|--json"
                   "-DCHECKS=plexus.received == 100;plexus.size == 4096;plexus.rtt_p50_us > 0"
                   -P ${PROJECT_SOURCE_DIR}/tests/scripts/json_checks.cmake)
endforeach()
set_tests_properties(tools.latency_probe_fast_to_cyclone tools.latency_probe_cyclone_to_fast PROPERTIES
                     LABELS "tools;multiprocess;interop" TIMEOUT 120)

# latency pipeline on a live system (it records for --duration, then computes).
add_test(NAME tools.latency_pipeline_live_cyclone
         COMMAND ${TOOLS_DIR}/pipeline_live.sh ${BIN_DIR} cyclone 226 ${CMAKE_BINARY_DIR}/test-runs/tools/pipeline_live)
set_tests_properties(tools.latency_pipeline_live_cyclone PROPERTIES LABELS "tools;multiprocess" TIMEOUT 120)

# Replay's other pacing modes: a fixed rate, and as fast as possible (depth-64 reliable
# writers, so no sample is overwritten before the recorder has it).
add_test(NAME tools.replay_rate_fast
         COMMAND ${TOOLS_DIR}/record_replay.sh ${BIN_DIR} fast 220 ${CMAKE_BINARY_DIR}/test-runs/tools/replay_rate_fast --rate 200)
add_test(NAME tools.replay_fast_cyclone
         COMMAND ${TOOLS_DIR}/record_replay.sh ${BIN_DIR} cyclone 221 ${CMAKE_BINARY_DIR}/test-runs/tools/replay_fast_cyclone
                 --fast --profile lockstep)
# Replay in lockstep standing in for the plant simulator: the services must compute exactly
# the recorded run's signals. Both vendors, and a Cyclone replay feeding Fast DDS services.
foreach(pair "fast;fast;222" "cyclone;cyclone;223" "fast;cyclone;224")
  list(GET pair 0 launch_vendor)
  list(GET pair 1 replay_vendor)
  list(GET pair 2 domain)
  set(name tools.replay_stands_in_for_plant_${launch_vendor}_${replay_vendor})
  add_test(NAME ${name}
           COMMAND ${TOOLS_DIR}/replay_stands_in.sh ${PLEXUS_CLI} ${PROJECT_SOURCE_DIR}/deploy/scenarios/wmr_output_feedback_rfid.yaml
                   ${launch_vendor} ${replay_vendor} ${domain} ${CMAKE_BINARY_DIR}/test-runs/tools/${name})
  set_tests_properties(${name} PROPERTIES LABELS "tools;multiprocess;lockstep" TIMEOUT 180)
endforeach()
set_tests_properties(tools.replay_rate_fast tools.replay_fast_cyclone PROPERTIES LABELS "tools;multiprocess" TIMEOUT 120)

# The periodic loop against cyclictest (short; priority refused -> warning, still runs).
# Exit 0 and measured figures (the sample count is the preallocated rate x duration: not a check).
add_test(NAME tools.latency_loop
         COMMAND ${CMAKE_COMMAND}
                 "-DCOMMAND=${PLEXUS_CLI}|latency|loop|--rate|1000|--duration|1|--json|--out|${CMAKE_BINARY_DIR}/test-runs/tools/loop"
                 "-DCHECKS=plexus.p50_us > 0;plexus.p99_us > 0;plexus.max_us > 0;plexus.count == 1000;cyclictest.count == 1000;cyclictest.p50_us > 0;ratio.p50 > 0;cpu >= 0;rounds == 4"
                 -P ${PROJECT_SOURCE_DIR}/tests/scripts/json_checks.cmake)
set_tests_properties(tools.latency_loop PROPERTIES LABELS "tools" TIMEOUT 60)

# Bad input: a one-line error naming the argument or file, exit 2.
plexus_refusal_test(tools.bad_topic_type LABELS cli tools
                    ERROR "--type: unknown message type 'Nope'"
                    COMMAND ${PLEXUS_CLI} topic echo tools/x --type Nope --domain 214 --wait 1)
plexus_refusal_test(tools.bad_vendor LABELS cli tools
                    ERROR "--dds: unknown DDS vendor 'opensplice'"
                    COMMAND ${PLEXUS_CLI} topic list --dds opensplice)
plexus_refusal_test(tools.missing_run_file LABELS cli tools
                    ERROR "/nonexistent/run.sqlite: no such file"
                    COMMAND ${PLEXUS_CLI} latency pipeline /nonexistent/run.sqlite)
plexus_refusal_test(tools.replay_missing_file LABELS cli tools
                    ERROR "/nonexistent/run.sqlite: no such file"
                    COMMAND ${PLEXUS_CLI} replay /nonexistent/run.sqlite)
plexus_refusal_test(tools.record_bad_file LABELS cli tools
                    ERROR "/nonexistent/dir/x.mcap: cannot create recording"
                    COMMAND ${PLEXUS_CLI} record -o /nonexistent/dir/x.mcap --domain 214)
plexus_refusal_test(tools.bad_loop_rate LABELS cli tools
                    ERROR "--rate: must be in \\(0, 100000\\] Hz"
                    COMMAND ${PLEXUS_CLI} latency loop --rate 0)
plexus_refusal_test(tools.bad_loop_rounds LABELS cli tools
                    ERROR "--rounds: must be in 1..100 and at most rate x duration \\(10\\)"
                    COMMAND ${PLEXUS_CLI} latency loop --rate 100 --duration 0.1 --rounds 20)
plexus_refusal_test(tools.bad_pingpong_size LABELS cli tools
                    ERROR "--size: must be in 0..1048576 bytes"
                    COMMAND ${PLEXUS_CLI} latency pingpong --size 2000000)
plexus_refusal_test(tools.bad_pingpong_pin LABELS cli tools
                    ERROR "--pin: must be auto, split, same or none, got 'fast'"
                    COMMAND ${PLEXUS_CLI} latency pingpong --pin fast)
plexus_refusal_test(tools.unknown_profile LABELS cli tools
                    ERROR "unknown QoS profile 'fastest'"
                    COMMAND ${PLEXUS_CLI} latency pingpong --profile fastest)
plexus_refusal_test(tools.bad_peer_vendor LABELS cli tools
                    ERROR "--peer-dds: unknown DDS vendor 'rti'"
                    COMMAND ${PLEXUS_CLI} latency pingpong --peer-dds rti)
set(CIRCLE ${PROJECT_SOURCE_DIR}/deploy/scenarios/unicycle_circle.yaml)
plexus_refusal_test(tools.launch_unknown_external LABELS cli tools
                    ERROR "--external plant: no such process \\(this scenario's: plant_simulator, "
                    COMMAND ${PLEXUS_CLI} launch ${CIRCLE} --external plant --domain 225)
plexus_refusal_test(tools.launch_unknown_vendor_process LABELS cli
                    ERROR "--vendor plant: no such process \\(this scenario's: plant_simulator, "
                    COMMAND ${PLEXUS_CLI} launch ${CIRCLE} --vendor plant=cyclone --domain 225)
plexus_refusal_test(tools.launch_record_bad_file LABELS cli tools
                    ERROR "/nonexistent/dir/x.mcap: cannot create recording"
                    COMMAND ${PLEXUS_CLI} launch ${CIRCLE} --record /nonexistent/dir/x.mcap --domain 225)

# A service's or robot's `dds` key must name a vendor (file, line and key in the error).
plexus_refusal_test(cli.scenario_bad_dds_key LABELS cli
                    ERROR "robots.r1.dds: expected fast or cyclone, got 'rti'"
                    COMMAND ${PLEXUS_CLI} sim ${CIRCLE} --set robots.r1.dds=rti)

# `process` groups (docs/scenarios.md): a valid name, and services of one process that agree.
set(PATH_CIRCLE ${PROJECT_SOURCE_DIR}/deploy/scenarios/path_following_circle.yaml)
plexus_refusal_test(cli.scenario_bad_process_name LABELS cli
                    ERROR "services.observer.process: letters, digits"
                    COMMAND ${PLEXUS_CLI} sim ${PATH_CIRCLE} "--set" "services.observer.process=my control")
plexus_refusal_test(cli.launch_process_group_disagrees LABELS cli
                    ERROR "members of process 'control' must agree on `dds`"
                    COMMAND ${PLEXUS_CLI} launch ${PATH_CIRCLE} --domain 225 --set services.observer.process=control
                            --set services.controller.process=control --set services.controller.dds=cyclone)
plexus_refusal_test(cli.launch_process_name_taken LABELS cli
                    ERROR "'path' is the name of service"
                    COMMAND ${PLEXUS_CLI} launch ${PATH_CIRCLE} --domain 225 --set services.observer.process=path)
# `loops:` (docs/scenarios.md): a loop's members, its process and its deadline are checked.
plexus_refusal_test(cli.scenario_loop_unknown_member LABELS cli
                    ERROR "loops.l.members: no robot or service 'nobody' in this scenario"
                    COMMAND ${PLEXUS_CLI} sim ${PATH_CIRCLE} --quiet "--set" "loops.l.members=[r1, nobody]")
plexus_refusal_test(cli.scenario_loop_one_member LABELS cli
                    ERROR "loops.l.members: a loop has at least two members"
                    COMMAND ${PLEXUS_CLI} sim ${PATH_CIRCLE} --quiet "--set" "loops.l.members=[r1]")
plexus_refusal_test(cli.scenario_loop_member_elsewhere LABELS cli
                    ERROR "loops.l.process: 'observer' already runs in process 'b'"
                    COMMAND ${PLEXUS_CLI} sim ${PATH_CIRCLE} --quiet "--set" "loops.l.members=[r1, observer]"
                            --set loops.l.process=a --set services.observer.process=b)
plexus_refusal_test(cli.scenario_loop_bad_deadline LABELS cli
                    ERROR "loops.l.deadline: must be in \\(0, 3600\\] s"
                    COMMAND ${PLEXUS_CLI} sim ${PATH_CIRCLE} --quiet "--set" "loops.l.members=[r1, observer]"
                            --set loops.l.deadline=0)
include(${CMAKE_CURRENT_LIST_DIR}/recordings.cmake)
# plexus service list (issue 31, docs/tools.md): two services alone, on Fast DDS and Cyclone
# DDS, listed from either vendor with their names, host, state, rate and typed topics. Domain 184.
# Domain 29: it used 184, tools.topic_info_incompatible_fast's (they ran in different phases only by their labels).
add_test(NAME tools.service_list
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/service_list.sh ${CMAKE_BINARY_DIR}/bin ${PROJECT_SOURCE_DIR}/deploy 29
                 ${CMAKE_BINARY_DIR}/test-runs/tools/service_list)
set_tests_properties(tools.service_list PROPERTIES LABELS "cli;multiprocess;light" TIMEOUT 60)
# plexus param (issue 31, docs/parameters.md): the observer's L and the controller's k1 changed
# while they run, refused values, the gain field and the command at the acknowledged step.
# In lockstep under plexus launch (the services on one vendor, the tool on the other; the
# recorded changes replay the launch's digest in plexus sim), domains 188-189; in realtime on
# services started alone across both vendors, recorded by plexus record, domains 190-191.
foreach(pair "fast;cyclone;188" "cyclone;fast;189")
  list(GET pair 0 vendor)
  list(GET pair 1 other)
  list(GET pair 2 domain)
  add_test(NAME tools.param_lockstep_${vendor}
           COMMAND ${CMAKE_CURRENT_LIST_DIR}/param_lockstep.sh ${CMAKE_BINARY_DIR}/bin ${PROJECT_SOURCE_DIR}/deploy
                   ${domain} ${CMAKE_BINARY_DIR}/test-runs/tools/param_lockstep_${vendor} ${vendor} ${other})
  math(EXPR rt_domain "${domain} + 2")
  add_test(NAME tools.param_realtime_${vendor}
           COMMAND ${CMAKE_CURRENT_LIST_DIR}/param_realtime.sh ${CMAKE_BINARY_DIR}/bin ${PROJECT_SOURCE_DIR}/deploy
                   ${rt_domain} ${CMAKE_BINARY_DIR}/test-runs/tools/param_realtime_${vendor} ${vendor} ${other})
  set_tests_properties(tools.param_lockstep_${vendor} tools.param_realtime_${vendor}
                       PROPERTIES LABELS "cli;multiprocess" TIMEOUT 120)
endforeach()
# A scenario's parameter_changes are checked at load, each at its own line, by the component's
# own validator; the param tool's arguments and files too (exit 2, one line).
set(RFID ${PROJECT_SOURCE_DIR}/deploy/scenarios/wmr_output_feedback_rfid.yaml)
plexus_refusal_test(cli.parameter_change_unknown_key LABELS cli
                    ERROR "parameter_changes.0.key: no tunable parameter 'observer.Lx' \\(tunable: observer.L, controller.k1"
                    COMMAND ${PLEXUS_CLI} sim ${RFID} --quiet
                            "--set" "parameter_changes=[{step: 10, key: observer.Lx, value: 1}]")
plexus_refusal_test(cli.parameter_change_bad_value LABELS cli
                    ERROR "parameter_changes.0.value: heading_observer: L must be finite and > 0 \\(got -1\\)"
                    COMMAND ${PLEXUS_CLI} sim ${RFID} --quiet
                            "--set" "parameter_changes=[{step: 10, key: L, value: -1}]")
plexus_refusal_test(cli.parameter_change_bad_step LABELS cli
                    ERROR "parameter_changes.0.step: must be a whole step in \\[0, 48000\\] \\(got 48001\\)"
                    COMMAND ${PLEXUS_CLI} sim ${RFID} --quiet
                            "--set" "parameter_changes=[{step: 48001, key: k1, value: 1}]")
plexus_refusal_test(cli.param_set_without_value LABELS cli
                    ERROR "plexus param: error: value is required"
                    COMMAND ${PLEXUS_CLI} param set "motion_controller controller" k1)
plexus_refusal_test(cli.param_changes_missing_file LABELS cli
                    ERROR "plexus param: error: recording: File does not exist: /nonexistent.mcap"
                    COMMAND ${PLEXUS_CLI} param changes /nonexistent.mcap)
