# plexus report (issue 19, "The report"): report.html in headless Chromium (report_html.sh:
# the table and every figure rendered, a screenshot that is not blank, and the check shown to
# catch a missing figure and an empty table), each paper's figure from its own single-family
# scenario (paper_figures.cmake), and the same from plexus launch --report. The grouping of fields into panels and the
# titles, labels and units of every figure are unit tests (report_figures_test, label unit).
set(report_runs ${CMAKE_BINARY_DIR}/test-runs/report)
add_test(NAME report.html_main_job
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/report_html.sh $<TARGET_FILE:plexus>
                 ${PROJECT_SOURCE_DIR}/deploy/scenarios/four_robots.yaml ${report_runs}/html_main_job 13
                 paper000.wmr.png,paper001.skid.png,paper002.bal.png,paper004.arm.png
                 --set duration=6 --set metrics.0.from=5 --set metrics.1.from=5)
add_test(NAME report.html_single_family
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/report_html.sh $<TARGET_FILE:plexus>
                 ${PROJECT_SOURCE_DIR}/deploy/scenarios/wmr_output_feedback_rfid.yaml ${report_runs}/html_single_family 3
                 paper000.r1.png)
set_tests_properties(report.html_main_job report.html_single_family PROPERTIES LABELS "report" TIMEOUT 300)

foreach(case "icr_terrain_switch_akf;paper001.r1.png;001" "icr_terrain_switch_prior;paper001.r1.png;001"
             "balance_ukf_ekf;paper002.r1.png;002" "arm_vdc_ekf;paper004.arm.png;004")
  list(GET case 0 scenario)
  list(GET case 1 figure)
  list(GET case 2 paper)
  add_test(NAME report.paper_figure.${scenario}
           COMMAND ${CMAKE_COMMAND} -DPLEXUS=$<TARGET_FILE:plexus> -DSCENARIO=${PROJECT_SOURCE_DIR}/deploy/scenarios/${scenario}.yaml
                   -DOUT=${report_runs}/${scenario} -DFIGURE=${figure} -DPAPER=${paper}
                   -P ${CMAKE_CURRENT_LIST_DIR}/paper_figures.cmake)
  set_tests_properties(report.paper_figure.${scenario} PROPERTIES LABELS "report" TIMEOUT 300)
endforeach()

# plexus launch --report writes the same report: balance_ukf_ekf over DDS (domain 90).
add_test(NAME report.launch_html
         COMMAND ${CMAKE_COMMAND} -DPLEXUS=$<TARGET_FILE:plexus> -DSCENARIO=${PROJECT_SOURCE_DIR}/deploy/scenarios/balance_ukf_ekf.yaml
                 -DOUT=${report_runs}/launch_html -DFIGURE=paper002.r1.png -DPAPER=002 -DLAUNCH=--dds|fast|--domain|90
                 -P ${CMAKE_CURRENT_LIST_DIR}/paper_figures.cmake)
set_tests_properties(report.launch_html PROPERTIES LABELS "report;multiprocess" TIMEOUT 300
                     RESOURCE_LOCK plexus_dds_domain_90)
