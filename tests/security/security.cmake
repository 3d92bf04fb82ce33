# DDS Security (issue 14, docs/security.md): secure closed loops on each vendor, the mixed
# vendor handshake, intruders without an identity or from another CA, and a capture of the
# secure traffic. Label `security`; DDS domains 100-109.
add_executable(security_probe ${CMAKE_CURRENT_LIST_DIR}/security_probe.cpp)
target_link_libraries(security_probe PRIVATE plexus_runtime CLI11::CLI11)
plexus_warnings(security_probe)

set(SEC_DIR ${CMAKE_CURRENT_LIST_DIR})
set(SEC_RUNS ${CMAKE_BINARY_DIR}/test-runs/security)
set(SEC_SCENARIO ${PROJECT_SOURCE_DIR}/deploy/scenarios/path_following_circle.yaml)
set(SEC_PROCESSES "plant_simulator|path|observer|controller")

# The PKIs (tools/security/make_test_pki.sh), checked with openssl: every other test needs them.
add_test(NAME security.pki COMMAND ${SEC_DIR}/pki_fixture.sh ${SEC_RUNS})
set_tests_properties(security.pki PROPERTIES LABELS "security" TIMEOUT 120 FIXTURES_SETUP security_pki)

# Secure closed loops: a lockstep `plexus launch` of paper 003's path following (plant, path,
# observer, controller and the launcher's clock, five participants, each with its identity)
# gives the digest and metrics of `plexus sim` with DDS Security on (everything encrypted).
function(plexus_secure_lockstep name domain pki)
  list(JOIN ARGN "|" extra)
  add_test(NAME security.lockstep_${name}
           COMMAND ${CMAKE_COMMAND} -DPLEXUS=$<TARGET_FILE:plexus> -DSCENARIO=${SEC_SCENARIO} -DOUT=${SEC_RUNS}/lockstep_${name}
                   -DDOMAIN=${domain} -DPKI=${pki} "-DPROCESSES=${SEC_PROCESSES}"
                   "-DLAUNCH_ARGS=--set|security.enabled=true|--set|security.pki=${pki}|${extra}"
                   -P ${SEC_DIR}/secure_lockstep.cmake)
  set_tests_properties(security.lockstep_${name} PROPERTIES LABELS "security;lockstep;multiprocess" TIMEOUT 300
                       FIXTURES_REQUIRED security_pki RESOURCE_LOCK plexus_dds_domain_${domain})
endfunction()
plexus_secure_lockstep(fast 100 ${SEC_RUNS}/pki --dds fast)
plexus_secure_lockstep(cyclone 101 ${SEC_RUNS}/pki --dds cyclone)
# Mixed vendors: observer and controller on Cyclone DDS, whose identities rank first (the
# fixture's `mixed` PKI), beside the plant, the path and the launcher on Fast DDS.
plexus_secure_lockstep(mixed 102 ${SEC_RUNS}/mixed --dds fast --vendor observer=cyclone --vendor controller=cyclone)

# A mixed deployment whose handshakes would fail (a Fast DDS observer whose identity ranks
# before the Cyclone DDS launcher's) is refused up front, naming the cause: exit 2.
add_test(NAME security.mixed_refused
         COMMAND ${PROJECT_SOURCE_DIR}/tests/scripts/expect_exit.sh 2
                 "security: Fast DDS process 'observer' \\(identity observer\\) and Cyclone DDS [a-z ]+'?[a-z_]*'? \\(identity [a-z_]+\\) cannot authenticate: the Fast DDS side's certificate subject ranks first .* DH\\+MODP-2048-256 public key that Cyclone DDS 0.10 cannot decode"
                 $<TARGET_FILE:plexus> launch ${SEC_SCENARIO} --quiet --domain 103 --out ${SEC_RUNS}/mixed_refused
                 --dds cyclone --vendor observer=fast --set security.enabled=true --set security.pki=${SEC_RUNS}/mixed)
set_tests_properties(security.mixed_refused PROPERTIES LABELS "security;cli" TIMEOUT 60 FIXTURES_REQUIRED security_pki)

# What secure Fast DDS <-> Cyclone DDS does, both data directions, both handshake orders.
add_test(NAME security.mixed_handshake
         COMMAND ${SEC_DIR}/mixed_handshake.sh $<TARGET_FILE:security_probe> ${SEC_RUNS}/mixed 104)
set_tests_properties(security.mixed_handshake PROPERTIES LABELS "security;interop;light" TIMEOUT 200
                     FIXTURES_REQUIRED security_pki RESOURCE_LOCK plexus_dds_domain_104)

# No identity, or one of another CA: no topic discovered, no sample injected; a secure
# plant_simulator started on its own (--security) on each vendor, intruders on both. In a
# network namespace of its own (tests/scripts/own_netns.sh): it asserts that nothing shows
# up on its domain, and a concurrent test's participant once did (docs/testing.md).
foreach(v "fast;105" "cyclone;106")
  list(GET v 0 vendor)
  list(GET v 1 domain)
  add_test(NAME security.intruders_${vendor}
           COMMAND ${PROJECT_SOURCE_DIR}/tests/scripts/own_netns.sh
                   ${SEC_DIR}/intruders.sh $<TARGET_FILE_DIR:plexus> ${PROJECT_SOURCE_DIR}/deploy/params/unicycle_robot.yaml
                   ${SEC_RUNS}/pki ${SEC_RUNS}/foreign ${vendor} ${domain})
  set_tests_properties(security.intruders_${vendor} PROPERTIES LABELS "security;multiprocess;slow;light" TIMEOUT 200
                       FIXTURES_REQUIRED security_pki RESOURCE_LOCK plexus_dds_domain_${domain})
endforeach()

# A capture of the traffic (tcpdump, in a network namespace the test creates): the marker and
# the value a probe publishes are in the clear without security and with the signing-only
# governance, and absent with the encrypting one.
foreach(v "fast;107" "cyclone;108")
  list(GET v 0 vendor)
  list(GET v 1 domain)
  add_test(NAME security.capture_${vendor}
           COMMAND ${SEC_DIR}/capture.sh $<TARGET_FILE:security_probe> ${SEC_RUNS}/pki ${vendor} ${domain})
  set_tests_properties(security.capture_${vendor} PROPERTIES LABELS "security;multiprocess" TIMEOUT 200
                       FIXTURES_REQUIRED security_pki RESOURCE_LOCK plexus_dds_domain_${domain})
endforeach()

# Bad security configuration: one line naming where it came from, exit 2.
set(EXPECT_EXIT ${PROJECT_SOURCE_DIR}/tests/scripts/expect_exit.sh)
plexus_refusal_test(security.bad_key
                    ERROR "bad_security.yaml:9: security.protection: unknown key"
                    COMMAND $<TARGET_FILE:plexus> sim ${SEC_DIR}/bad_security.yaml)
plexus_refusal_test(security.no_pki
                    ERROR "--set security.enabled=true: security.enabled: DDS Security needs `pki`"
                    COMMAND $<TARGET_FILE:plexus> launch ${SEC_SCENARIO} --quiet --out ${SEC_RUNS}/no_pki
                            --set security.enabled=true)
plexus_refusal_test(security.unknown_process
                    ERROR "security.identities.bogus: no process 'bogus' in this scenario \\(processes: plexus_launch, plant_simulator, path, observer, controller\\)"
                    COMMAND $<TARGET_FILE:plexus> launch ${SEC_SCENARIO} --quiet --out ${SEC_RUNS}/unknown_process
                            --set security.enabled=true --set security.pki=${SEC_RUNS}/pki
                            --set security.identities.bogus=observer)
plexus_refusal_test(security.identity_of_another_ca
                    ERROR "security.identities.observer: identity 'probe_pub': .*/foreign/identities/probe_pub/cert.pem: not signed by the identity CA .*/pki/identity_ca.pem"
                    COMMAND $<TARGET_FILE:plexus> launch ${SEC_SCENARIO} --quiet --out ${SEC_RUNS}/another_ca
                            --set security.enabled=true --set security.pki=${SEC_RUNS}/pki
                            --set security.identities.observer=${SEC_RUNS}/foreign/identities/probe_pub)
plexus_refusal_test(security.missing_identity
                    ERROR "security.pki: identity 'plant_simulator': .*/foreign/identities/plant_simulator/cert.pem: no such file \\(process 'plant_simulator' uses identity 'plant_simulator' unless security.identities names another; tools/security/make_test_pki.sh PKI plant_simulator creates it\\)"
                    COMMAND $<TARGET_FILE:plexus> launch ${SEC_SCENARIO} --quiet --out ${SEC_RUNS}/missing_identity
                            --set security.enabled=true --set security.pki=${SEC_RUNS}/foreign)
plexus_refusal_test(security.service_identity_without_pki
                    ERROR "plant_simulator: error: --identity r1: needs --security PKI_FOLDER"
                    COMMAND $<TARGET_FILE:plant_simulator> --robot r1
                            --params ${PROJECT_SOURCE_DIR}/deploy/params/unicycle_robot.yaml --identity r1)
plexus_refusal_test(security.tool_missing_pki
                    ERROR "plexus topic: error: --security /nonexistent/pki: no such folder"
                    COMMAND $<TARGET_FILE:plexus> topic list --security /nonexistent/pki)
plexus_refusal_test(security.pki_script_bad_domains
                    ERROR "make_test_pki.sh: --domains: expected MIN-MAX within 0..230 \\(Cyclone DDS 0.10 refuses"
                    COMMAND ${PROJECT_SOURCE_DIR}/tools/security/make_test_pki.sh ${SEC_RUNS}/bad_domains
                            --domains 0-231)
set_tests_properties(security.bad_key security.no_pki security.unknown_process security.identity_of_another_ca
                     security.missing_identity security.service_identity_without_pki security.tool_missing_pki
                     security.pki_script_bad_domains PROPERTIES LABELS "security;cli" TIMEOUT 60 FIXTURES_REQUIRED security_pki)
# A governance document signed by another permissions CA, and an identity whose key is not its
# certificate's (a folder mixing two identities).
plexus_refusal_test(security.governance_of_another_ca
                    ERROR "plexus topic: error: --security .*/pki: identity 'plexus_topic': .*/foreign/governance.p7s: not signed by the permissions CA .*/pki/permissions_ca.pem"
                    COMMAND $<TARGET_FILE:plexus> topic list --security ${SEC_RUNS}/pki
                            --governance ${SEC_RUNS}/foreign/governance.p7s)
add_test(NAME security.key_of_another_identity
         COMMAND bash -c "rm -rf ${SEC_RUNS}/mixed_up && mkdir -p ${SEC_RUNS}/mixed_up && cp ${SEC_RUNS}/pki/identities/observer/cert.pem ${SEC_RUNS}/pki/identities/observer/permissions.p7s ${SEC_RUNS}/mixed_up/ && cp ${SEC_RUNS}/pki/identities/controller/key.pem ${SEC_RUNS}/mixed_up/ && exec ${EXPECT_EXIT} 2 \"identity 'mixed_up': .*/mixed_up/key.pem: not the key of .*/mixed_up/cert.pem\" $<TARGET_FILE:localisation_observer> --params ${PROJECT_SOURCE_DIR}/deploy/params/heading_observer.yaml --security ${SEC_RUNS}/pki --identity ${SEC_RUNS}/mixed_up")
set_tests_properties(security.governance_of_another_ca security.key_of_another_identity PROPERTIES LABELS "security;cli"
                     TIMEOUT 60 FIXTURES_REQUIRED security_pki)

# Fast DDS 2.9 rejects payloads signed on their own when their length is not a multiple of 4
# (why the signing governance leaves them to the submessage signature), and its errors go to
# stderr, not into a tool's output.
add_test(NAME security.fast_signed_payload
         COMMAND ${SEC_DIR}/fast_signed_payload.sh $<TARGET_FILE:security_probe> ${SEC_RUNS}/pki 109)
set_tests_properties(security.fast_signed_payload PROPERTIES LABELS "security;interop" TIMEOUT 120
                     FIXTURES_REQUIRED security_pki RESOURCE_LOCK plexus_dds_domain_109)

# A secure Cyclone DDS process exits cleanly while encrypted traffic arrives (15 exits).
add_test(NAME security.cyclone_clean_exit
         COMMAND ${SEC_DIR}/cyclone_clean_exit.sh $<TARGET_FILE:security_probe> ${SEC_RUNS}/pki 109 15)
set_tests_properties(security.cyclone_clean_exit PROPERTIES LABELS "security;multiprocess" TIMEOUT 300
                     FIXTURES_REQUIRED security_pki RESOURCE_LOCK plexus_dds_domain_109)
