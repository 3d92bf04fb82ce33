/* native_cyclone_peer: a plain Cyclone DDS C program, built only from the idlc output of
 * plexus's IDL (no plexus code), that exchanges Pose2D and JointState samples with plexus
 * processes. Values follow tests/peers/simple_values.hpp.
 *
 *   native_cyclone_peer pub|sub DOMAIN COUNT
 *
 * Traffic stays on loopback with unicast discovery, like plexus's own configuration. */
#include <dds/dds.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plexus/msg/joint.h"
#include "plexus/msg/pose.h"

static const char* kConfig =
    "<CycloneDDS><Domain Id=\"any\"><General><Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
    "<AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex>"
    "<MaxAutoParticipantIndex>31</MaxAutoParticipantIndex><Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>"
    "</Domain></CycloneDDS>";

static void fill_pose(plexus_msg_Pose2D* m, uint64_t seq) {
  memset(m, 0, sizeof *m);
  m->header.seq_num = seq;
  m->x = (double)seq;
  m->y = -0.5 * (double)seq;
  m->theta = 0.01 * (double)seq;
}

static int check_pose(const plexus_msg_Pose2D* m) {
  const uint64_t s = m->header.seq_num;
  return s > 0 && m->x == (double)s && m->y == -0.5 * (double)s && m->theta == 0.01 * (double)s;
}

static void fill_joints(plexus_msg_JointState* m, uint64_t seq) {
  memset(m, 0, sizeof *m);
  m->header.seq_num = seq;
  m->count = 7;
  for (int i = 0; i < 16; ++i) {
    m->position[i] = (double)seq + i;
    m->velocity[i] = -(double)i;
    m->effort[i] = 0.5 * (double)seq * i;
  }
}

static int check_joints(const plexus_msg_JointState* m) {
  const uint64_t s = m->header.seq_num;
  if (s == 0 || m->count != 7) return 0;
  for (int i = 0; i < 16; ++i)
    if (m->position[i] != (double)s + i || m->velocity[i] != -(double)i || m->effort[i] != 0.5 * (double)s * i) return 0;
  return 1;
}

int main(int argc, char** argv) {
  if (argc != 4 || (strcmp(argv[1], "pub") != 0 && strcmp(argv[1], "sub") != 0)) {
    fprintf(stderr, "usage: native_cyclone_peer pub|sub DOMAIN COUNT\n");
    return 2;
  }
  const int pub = strcmp(argv[1], "pub") == 0;
  const dds_domainid_t domain = (dds_domainid_t)atoi(argv[2]);
  const int count = atoi(argv[3]);
  dds_create_domain(domain, kConfig);
  dds_qos_t* pq = dds_create_qos();
  dds_qset_entity_name(pq, pub ? "native_cyclone_peer pub" : "native_cyclone_peer sub");
  const dds_entity_t pp = dds_create_participant(domain, pq, NULL);
  dds_delete_qos(pq);
  if (pp < 0) return 1;
  const dds_entity_t tpose = dds_create_topic(pp, &plexus_msg_Pose2D_desc, "native/Pose2D", NULL, NULL);
  const dds_entity_t tjoint = dds_create_topic(pp, &plexus_msg_JointState_desc, "native/JointState", NULL, NULL);
  dds_qos_t* q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, count);
  /* transient-local, as plexus_test_peer: a reader matching just after the writer wrote
     still gets every sample */
  dds_qset_durability(q, DDS_DURABILITY_TRANSIENT_LOCAL);
  const dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
  dds_qset_data_representation(q, 1, &xcdr1);
  const dds_time_t deadline = dds_time() + DDS_SECS(40);
  int rc = 0;
  if (pub) {
    const dds_entity_t wpose = dds_create_writer(pp, tpose, q, NULL);
    const dds_entity_t wjoint = dds_create_writer(pp, tjoint, q, NULL);
    dds_publication_matched_status_t s1 = {0}, s2 = {0};
    while ((s1.current_count == 0 || s2.current_count == 0) && dds_time() < deadline) {
      dds_get_publication_matched_status(wpose, &s1);
      dds_get_publication_matched_status(wjoint, &s2);
      dds_sleepfor(DDS_MSECS(10));
    }
    if (s1.current_count == 0 || s2.current_count == 0) {
      fprintf(stderr, "native_cyclone_peer pub: no reader matched\n");
      return 1;
    }
    for (int k = 1; k <= count; ++k) {
      plexus_msg_Pose2D p;
      plexus_msg_JointState j;
      fill_pose(&p, (uint64_t)k);
      fill_joints(&j, (uint64_t)k);
      if (dds_write(wpose, &p) < 0 || dds_write(wjoint, &j) < 0) rc = 1;
    }
    while ((s1.current_count > 0 || s2.current_count > 0) && dds_time() < deadline) {
      dds_get_publication_matched_status(wpose, &s1);
      dds_get_publication_matched_status(wjoint, &s2);
      dds_sleepfor(DDS_MSECS(20));
    }
    printf("native_cyclone_peer pub: wrote %d Pose2D and JointState samples\n", count);
  } else {
    const dds_entity_t rpose = dds_create_reader(pp, tpose, q, NULL);
    const dds_entity_t rjoint = dds_create_reader(pp, tjoint, q, NULL);
    int got_pose = 0, got_joint = 0, bad = 0;
    while ((got_pose < count || got_joint < count) && dds_time() < deadline) {
      plexus_msg_Pose2D p;
      plexus_msg_JointState j;
      void* sp = &p;
      void* sj = &j;
      dds_sample_info_t info;
      while (dds_take(rpose, &sp, &info, 1, 1) > 0)
        if (info.valid_data) check_pose(&p) ? ++got_pose : ++bad;
      while (dds_take(rjoint, &sj, &info, 1, 1) > 0)
        if (info.valid_data) check_joints(&j) ? ++got_joint : ++bad;
      dds_sleepfor(DDS_MSECS(5));
    }
    printf("native_cyclone_peer sub: Pose2D %d/%d, JointState %d/%d, wrong values %d\n", got_pose, count, got_joint,
           count, bad);
    rc = (got_pose == count && got_joint == count && bad == 0) ? 0 : 1;
  }
  dds_delete_qos(q);
  dds_delete(pp);
  return rc;
}
