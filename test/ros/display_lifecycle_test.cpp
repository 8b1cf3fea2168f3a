// The DressedHuman display in a real rviz VisualizationManager (on the test's X server): 1000
// enable/disable cycles with resets and property changes, without a crash, an error status or
// resident memory growing by more than 5 %; and a bone frame that goes missing from TF is
// reported on its own and recovers by itself; unseen relief is drawn with the plain material;
// automatic vertex evaluation picks the CPU on this software renderer; one display draws every
// human in TF, as they come and go, and every human of a crowd topic, refusing bad messages; a
// robot description set after the display started is picked up.
#include <algorithm>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "display_lifecycle_fixture.h"

namespace {

using namespace display_lifecycle;

TEST_F(DisplayLifecycleTest, ThousandCyclesWithoutGrowth) {
  ASSERT_NE(display_, nullptr) << "the dressed_human/DressedHuman plugin did not load";
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(60.0);
  while ((level() != rviz::StatusProperty::Ok || !reported()) && ros::WallTime::now() < deadline) frame();
  ASSERT_TRUE(reported()) << "the human was never built: is the skeleton publishing TF?";
  ASSERT_TRUE(drawnOnScreen()) << "the display reports the human but it is not on screen\n" << allStatuses();
  ASSERT_EQ(level(), rviz::StatusProperty::Ok);
  legs_ = dynamic_cast<rviz::VectorProperty*>(display_->subProp("Body Shape")->subProp("Legs"));
  ASSERT_NE(legs_, nullptr) << "no Body Shape / Legs property";

  const char* relief[] = {"Bump mapping", "Flat", "Bump mapping", "Flat", "Bump mapping", "Displaced geometry"};
  const char* lod[] = {"Automatic", "Fixed"};
  auto cycle = [&](int i) {
    display_->setEnabled(false);
    frame();
    display_->setEnabled(true);
    display_->subProp("Relief")->setValue(relief[i % 6]);
    display_->subProp("Show Skeleton")->setValue(i % 4 == 1);
    display_->subProp("Level of Detail")->setValue(lod[(i / 2) % 2]);
    display_->subProp("Tessellation Level")->setValue(2 + i % 7);
    display_->subProp("Vertex Evaluation")->setValue(i % 3 == 2 ? "CPU" : "GPU");
    display_->subProp("Skin Relief Strength")->setValue(0.5 + 0.1 * (i % 10));
    if (i % 50 == 0) display_->subProp("Skin Seed")->setValue(1 + (i / 50) % 3);
    if (i % 10 == 0) display_->reset();
    if (i % 20 == 7) {
      // A new body shape every 20 cycles (rebuilds skin and garments); every 100th is out of
      // range (an error status, the old shape kept) and is put right on the next cycle.
      const float legs = i % 100 == 47 ? 0.1f : 0.8f + 0.05f * static_cast<float>(i % 9);
      legs_->setVector(Ogre::Vector3(legs, legs, 1.0f));
    }
    if (i % 100 == 48) legs_->setVector(Ogre::Vector3(1.0f, 1.0f, 1.0f));
    frames(2);
    // Only the deliberately bad body shape may be an error; anything else fails the cycle.
    const std::string errors = unexpectedErrors("Body Shape");
    EXPECT_TRUE(errors.empty()) << "cycle " << i << ":\n" << errors;
    return errors.empty();
  };
  // Warm-up: caches, textures, every level and relief mode, the largest buffers. Mesa's
  // software GL driver keeps growing slowly under this churn (heaptrack: the unfreed blocks are
  // allocated inside swrast_dri.so, none in this package), hence the long warm-up; and longer
  // than tf2's cache time (10 s), which fills with the skeleton's transforms.
  const ros::WallTime warm = ros::WallTime::now() + ros::WallDuration(15.0);
  for (int i = 0; i < 300 || ros::WallTime::now() < warm; ++i) ASSERT_TRUE(cycle(i));
  const long before = residentKilobytes();
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(cycle(i));
  frames(30);
  const long after = residentKilobytes();
  std::fprintf(stderr, "resident memory: %ld kB before, %ld kB after 1000 cycles (%+.2f %%)\n", before, after,
               100.0 * static_cast<double>(after - before) / static_cast<double>(before));
  EXPECT_LE(after, before + before / 20);
  EXPECT_EQ(level(), rviz::StatusProperty::Ok);
}

// Fragment programs of the display's materials ("dressed_human/<display>/.../<part>"), by part.
std::vector<std::string> fragmentPrograms() {
  std::vector<std::string> names;
  auto materials = Ogre::MaterialManager::getSingleton().getResourceIterator();
  while (materials.hasMoreElements()) {
    Ogre::ResourcePtr resource = materials.getNext();
    const std::string name = resource->getName();
    const auto endsWith = [&](const std::string& end) {
      return name.size() > end.size() && name.compare(name.size() - end.size(), end.size(), end) == 0;
    };
    if (name.rfind("dressed_human/", 0) != 0 || !(endsWith("/skin") || endsWith("/skirt") || endsWith("/jacket")))
      continue;
    auto material = Ogre::static_pointer_cast<Ogre::Material>(resource);
    names.push_back(material->getTechnique(0)->getPass(0)->getFragmentProgramName());
  }
  return names;
}

// The relief is drawn with the plain material where its features are 3 pixels or fewer on
// screen: the default view (about 9 m away) in a window 60 pixels high (every relief under a
// pixel: lit per vertex), 1200 pixels high with the camera 2 m from the human (the garments' folds,
// a few centimetres, are tens of pixels: their oriented folds; the skin's cells, at their true
// size of about a millimetre since issue 40, under a pixel: plain), 0.5 m away (the skin's cells
// about 5 px: its relief too), and back; "Hide Unseen Relief" off keeps the relief whatever the
// size. (Until issue 21 the garments' folds were three times as large and showed from the default
// view too; until issue 40 the skin's cells were a twelfth of a patch, 8 mm, and showed from 2 m.)
TEST_F(DisplayLifecycleTest, UnseenReliefIsDrawnWithThePlainMaterial) {
  ASSERT_NE(display_, nullptr) << "the dressed_human/DressedHuman plugin did not load";
  display_->subProp("Relief")->setValue("Bump mapping");
  display_->subProp("Hide Unseen Relief")->setValue(true);
  auto count = [](const std::vector<std::string>& programs, const std::string& name) {
    return std::count(programs.begin(), programs.end(), name);
  };
  // Too small for the relief is here also too small for per-pixel lighting: lit per vertex.
  const std::string vertex_lit = "dressed_human/VertexLitFragment", plain = "dressed_human/PlainSurfaceFragment",
                    skin = "dressed_human/ReliefSurfaceFragment", folds = "dressed_human/FoldCoordinateFragment";
  struct View {
    int height;
    QVariant distance;
    std::string skin_program, garment_program;
  };
  const std::vector<View> views{{60, QVariant(), vertex_lit, vertex_lit},
                                {1200, QVariant(2.0), plain, folds},
                                {1200, QVariant(0.5), skin, folds},
                                {60, QVariant(), vertex_lit, vertex_lit}};
  for (const View& view : views) {
    viewHuman(view.height, view.distance);
    const std::vector<std::string> programs = fragmentPrograms();
    std::string listed;
    for (const std::string& program : programs) listed += program + " ";
    ASSERT_EQ(programs.size(), 3u) << "skin, skirt and jacket";
    const std::string where = std::to_string(view.height) + " px at " +
                              (view.distance.isValid() ? view.distance.toString().toStdString() + " m" : "rviz's") +
                              ": " + listed;
    if (view.skin_program == view.garment_program) {
      EXPECT_EQ(count(programs, view.skin_program), 3) << where;
    } else {
      EXPECT_EQ(count(programs, view.skin_program), 1) << where;
      EXPECT_EQ(count(programs, view.garment_program), 2) << where;
    }
  }
  display_->subProp("Hide Unseen Relief")->setValue(false);
  frames(5);
  EXPECT_EQ(count(fragmentPrograms(), skin) + count(fragmentPrograms(), folds), 3) << "Hide Unseen Relief off";
  display_->subProp("Hide Unseen Relief")->setValue(true);
  restoreView();
}

// What the clothes cover is left out (fewer triangles drawn) while the human is too small for
// its 2 cm gap to be seen into, and drawn again up close or with 'Hide Covered Surfaces' off.
TEST_F(DisplayLifecycleTest, CoveredSurfacesAreLeftOutOnlyWhileTooSmallToSee) {
  ASSERT_NE(display_, nullptr) << "the dressed_human/DressedHuman plugin did not load";
  // A fixed level: the count then does not follow the walk.
  display_->subProp("Level of Detail")->setValue("Fixed");
  display_->subProp("Tessellation Level")->setValue(4);
  const auto drawnTriangles = [&](bool hide, bool near) {
    display_->subProp("Hide Covered Surfaces")->setValue(hide);
    viewHuman(near);
    const rviz::StatusProperty* surfaces = status("Surfaces");
    const QStringList words = surfaces ? surfaces->getValue().toString().split(' ') : QStringList();
    const int at = words.indexOf("triangles");
    return at > 0 ? words[at - 1].toInt() : -1;
  };
  const int all = drawnTriangles(false, false);
  ASSERT_GT(all, 0) << allStatuses();
  EXPECT_LT(drawnTriangles(true, false), 0.85 * all) << "small on screen: the covered skin left out";
  EXPECT_EQ(drawnTriangles(true, true), all) << "2 m away in a large view: everything drawn";
  EXPECT_LT(drawnTriangles(true, false), 0.85 * all) << "small again";
  display_->subProp("Hide Covered Surfaces")->setValue(true);
  display_->subProp("Level of Detail")->setValue("Automatic");
  restoreView();
}

// While the human is small the garments' insides are culled with the covered skin: it must look
// the same. A garment wound the wrong way round would lose its outside and open a hole onto
// the background where the skin under it is left out too.
TEST_F(DisplayLifecycleTest, ASmallHumanLooksTheSameWithItsInsidesCulled) {
  ASSERT_NE(display_, nullptr) << "the dressed_human/DressedHuman plugin did not load";
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(60.0);
  while (!reported() && ros::WallTime::now() < deadline) frame();
  ASSERT_TRUE(reported()) << allStatuses();
  // 4 m away in a 240 px view: about 70 px a metre, the 2 cm gap past hems under 1.5 px (small).
  const auto figureWithCoveredHidden = [&](bool hide) {
    display_->subProp("Hide Covered Surfaces")->setValue(hide);
    focusOnHuman();
    manager_->getViewManager()->getCurrent()->subProp("Distance")->setValue(4.0);
    frames(10);
    return figurePixels();
  };
  for (const char* outfit : {"one_piece", "jacket_pants", "jacket_skirt"}) {
    display_->subProp("Outfit")->setValue(outfit);
    frames(5);
    const int everything = figureWithCoveredHidden(false);
    ASSERT_GT(everything, 1500) << outfit << ": the human is not drawn large enough to judge\n" << allStatuses();
    const int culled = figureWithCoveredHidden(true);
    // The walk moves on between the two shots (10 frames): the silhouette changes by a few %.
    EXPECT_NEAR(culled, everything, 0.05 * everything)
        << outfit << ": figure pixels with the insides culled and the covered skin left out";
  }
  display_->subProp("Hide Covered Surfaces")->setValue(true);
  restoreView();
}

// Under Xvfb the GL is Mesa's llvmpipe: "Automatic" (the default) evaluates the vertices on the
// CPU and says why; "GPU" asked for explicitly is obeyed.
TEST_F(DisplayLifecycleTest, AutomaticVertexEvaluationPicksTheCpuOnASoftwareRenderer) {
  ASSERT_NE(display_, nullptr) << "the dressed_human/DressedHuman plugin did not load";
  display_->subProp("Vertex Evaluation")->setValue("Automatic");
  frames(3);
  const rviz::StatusProperty* automatic = status("Vertex Evaluation");
  ASSERT_NE(automatic, nullptr) << allStatuses();
  const std::string text = automatic->getValue().toString().toStdString();
  EXPECT_NE(text.find("CPU (Automatic)"), std::string::npos) << text;
  EXPECT_NE(text.find("llvmpipe"), std::string::npos) << text;
  display_->subProp("Vertex Evaluation")->setValue("GPU");
  frames(3);
  EXPECT_EQ(status("Vertex Evaluation"), nullptr) << allStatuses();
  display_->subProp("Vertex Evaluation")->setValue("Automatic");
}

// The test publishes the TF of a second human itself (frames suffixed _9, all joints at zero),
// so that it can leave one joint out: the knee's first link, which the left shank hangs from.
TEST_F(DisplayLifecycleTest, MissingBoneFrameIsReportedAloneAndRecovers) {
  ASSERT_NE(display_, nullptr) << "the dressed_human/DressedHuman plugin did not load";
  std::string description;
  ASSERT_TRUE(ros::param::get("missing_bone_description", description))
      << "the .test file sets missing_bone_description";
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(description);
  ASSERT_TRUE(model != nullptr);
  display_->subProp("Robot Description")->setValue("missing_bone_description");
  tf2_ros::TransformBroadcaster broadcaster;
  const auto publish = [&](bool with_knee) {
    broadcaster.sendTransform(restPoseTransforms(*model, "", 0.0, with_knee ? "" : "l_knee_ry_link_9"));
  };
  // Runs frames for `seconds` while publishing, until `done` holds; returns whether it did.
  const auto runUntil = [&](bool with_knee, double seconds, const std::function<bool()>& done) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::WallTime::now() < deadline) {
      publish(with_knee);
      frames(2);
      ros::WallDuration(0.01).sleep();
      if (done()) return true;
    }
    return false;
  };
  const QString knee = "Frame l_knee_9";
  ASSERT_TRUE(runUntil(true, 60.0, [&] { return reported() && level() == rviz::StatusProperty::Ok; }))
      << "the second human was never drawn:\n"
      << unexpectedErrors("");
  // Without the knee's link, exactly one status: the shank's frame. Bones below it (the foot)
  // are still found, relative to the shank.
  ASSERT_TRUE(
      runUntil(false, 30.0, [&] { return status(knee) && status(knee)->getLevel() == rviz::StatusProperty::Error; }))
      << "no error status '" << knee.toStdString() << "':\n"
      << unexpectedErrors("") << allStatuses();
  runUntil(false, 1.0, [] { return false; });
  EXPECT_EQ(unexpectedErrors(knee), "") << "errors other than the missing frame";
  ASSERT_NE(status(knee), nullptr);
  EXPECT_NE(status(knee)->getValue().toString().toStdString().find("l_knee"), std::string::npos)
      << status(knee)->getValue().toString().toStdString();
  // The link returns: the error goes by itself.
  EXPECT_TRUE(runUntil(true, 30.0, [&] { return status(knee) == nullptr && level() == rviz::StatusProperty::Ok; }))
      << "still reported after the frame returned:\n"
      << unexpectedErrors("");
}

// One display for every human in TF: humans published by this test (body_7, body_8, beside the
// node's body) appear in the display, one that stops publishing leaves it after Human Timeout with
// every status it set, and comes back; then 1000 rebuilds of the whole crowd (each removes and
// adds every human, as a crowd file or Vary change does) without leaking the humans.
TEST_F(DisplayLifecycleTest, CrowdHumansComeAndGoWithoutGrowth) {
  ASSERT_NE(display_, nullptr) << "the dressed_human/DressedHuman plugin did not load";
  std::string description;
  ASSERT_TRUE(ros::param::get("robot_description", description));
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(description);
  ASSERT_TRUE(model != nullptr);
  display_->subProp("Robot Description")->setValue("robot_description");
  display_->subProp("Human Timeout")->setValue(1.0);
  display_->subProp("Humans")->setValue("Every Human in TF");
  tf2_ros::TransformBroadcaster broadcaster;
  std::set<std::string> published = {"_7", "_8"};
  const auto runUntil = [&](double seconds, const std::function<bool()>& done) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
    do {
      double x = 1.0;
      for (const std::string& suffix : published)
        broadcaster.sendTransform(restPoseTransforms(*model, suffix, x += 1.0));
      frames(2);
      ros::WallDuration(0.01).sleep();
      if (done()) return true;
    } while (ros::WallTime::now() < deadline);
    return false;
  };
  const auto says = [&](const QString& name, const std::string& start) {
    return status(name) != nullptr && status(name)->getValue().toString().toStdString().rfind(start, 0) == 0;
  };
  const auto statusesOf = [&](const std::string& suffix) {
    std::string found;
    for (const std::string& line : {"TF body" + suffix, "Pose body" + suffix, "Frame body" + suffix,
                                    "Frame waist" + suffix, "Model body" + suffix}) {
      if (status(QString::fromStdString(line))) found += line + "\n";
    }
    return found;
  };
  ASSERT_TRUE(runUntil(30.0, [&] { return says("Humans", "3 in TF") && says("Surfaces", "3 humans"); }))
      << "the node's human and two published ones were never all drawn:\n"
      << allStatuses();
  EXPECT_EQ(unexpectedErrors(""), "");

  published.erase("_8");
  ASSERT_TRUE(runUntil(10.0, [&] { return says("Humans", "2 in TF") && says("Surfaces", "2 humans"); }))
      << "body_8 stopped but stayed:\n"
      << allStatuses();
  EXPECT_EQ(statusesOf("_8"), "") << "statuses of a human that left";
  published.insert("_8");
  ASSERT_TRUE(runUntil(10.0, [&] { return says("Humans", "3 in TF") && says("Surfaces", "3 humans"); }))
      << "body_8 did not come back:\n"
      << allStatuses();

  // A cycle: one frame with this test's TF, and (rebuild) the whole crowd removed and added again.
  const auto cycle = [&](int i, bool rebuild) {
    if (rebuild) display_->subProp("Vary Unlisted Humans")->setValue(i % 2 == 0);
    runUntil(0.0, [] { return true; });
    const std::string errors = unexpectedErrors("");
    EXPECT_TRUE(errors.empty() && says("Humans", "3 in TF")) << "cycle " << i << ":\n" << allStatuses();
    return errors.empty();
  };
  // Warm-up: at least 100 rebuilds, and longer than tf2's cache time (10 s). The same cycles
  // without rebuilds measure what grows anyway (heaptrack: tf2's TimeCache of the transforms
  // published here, and Mesa's software driver). Beyond that, each human created may leave at
  // most 16 kB: a human holds about 9 MB (bench/rviz_scaling.py), so a leaked model, mesh or
  // material fails at once. Measured: about 6 kB per human, not yet attributed (the largest
  // blocks heaptrack finds alive at the end are tf2's cache and Mesa's driver).
  const ros::WallTime warm = ros::WallTime::now() + ros::WallDuration(15.0);
  for (int i = 0; i < 100 || ros::WallTime::now() < warm; ++i) ASSERT_TRUE(cycle(i, true));
  const long start = residentKilobytes();
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(cycle(i, false));
  const long before = residentKilobytes();
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(cycle(i, true));
  runUntil(1.0, [] { return false; });
  const long after = residentKilobytes();
  std::fprintf(stderr,
               "crowd of 3: resident memory %ld kB, %ld kB after 1000 frames without rebuilds (%+ld kB), %ld kB "
               "after 1000 rebuilds (%+ld kB, %+.2f %%)\n",
               start, before, before - start, after, after - before,
               100.0 * static_cast<double>(after - before) / static_cast<double>(before));
  constexpr long kHumansCreated = 3 * 1000;
  constexpr long kKilobytesPerHuman = 16;
  EXPECT_LE(after - before, std::max(before - start, 0L) + kHumansCreated * kKilobytesPerHuman);
  EXPECT_TRUE(says("Surfaces", "3 humans")) << allStatuses();
  display_->subProp("Humans")->setValue("Robot Description");
}

// "Humans: From Topic": humans come with the crowd message, leave once drawn to their last pose
// when a message leaves them out (a second after the topic falls silent), and a bad human or
// message is refused and named while the others stay drawn.
TEST_F(DisplayLifecycleTest, CrowdTopicHumansComeGoAndBadMessagesAreNamed) {
  ASSERT_NE(display_, nullptr) << "the dressed_human/DressedHuman plugin did not load";
  ros::NodeHandle node;
  ros::Publisher publisher = node.advertise<dressed_human::Crowd>("/test_crowd", 10);
  display_->subProp("Robot Description")->setValue("robot_description");
  display_->subProp("Humans")->setValue("From Topic");
  display_->subProp("Topic")->setValue("/test_crowd");
  const auto human = [](const std::string& id, double x) {
    dressed_human::HumanState state;
    state.id = id;
    state.root.position.x = x;
    state.root.position.z = 1.0;
    state.root.orientation.w = 1.0;
    state.joint_angles.assign(48, 0.1f);
    state.stature = 1.0f;
    return state;
  };
  // Sends `message` (its stamp now) with each frame until `done` or `seconds` pass.
  ros::WallTime last_sent;
  const auto runUntil = [&](dressed_human::Crowd message, double seconds, const std::function<bool()>& done) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
    do {
      message.header.stamp = ros::Time::now();
      if (message.header.frame_id.empty()) message.header.frame_id = "world";
      publisher.publish(message);
      last_sent = ros::WallTime::now();
      frames(2);
      ros::WallDuration(0.02).sleep();
      if (done()) return true;
    } while (ros::WallTime::now() < deadline);
    return false;
  };
  const auto says = [&](const QString& name, const std::string& part) {
    return status(name) != nullptr && status(name)->getValue().toString().toStdString().find(part) != std::string::npos;
  };
  dressed_human::Crowd two;
  two.humans = {human("3", 2.0), human("4", 4.0)};
  two.humans[1].stature = 1.1f;
  ASSERT_TRUE(
      runUntil(two, 30.0, [&] { return says("Humans", "2 from '/test_crowd'") && says("Surfaces", "2 humans"); }))
      << "the two humans of the message were never drawn:\n"
      << allStatuses();
  EXPECT_EQ(unexpectedErrors(""), "");

  dressed_human::Crowd one;
  one.humans = {human("3", 2.0)};
  const ros::WallTime dropped = last_sent;  // the last message with human 4
  ASSERT_TRUE(runUntil(one, 5.0, [&] { return says("Humans", "1 from") && says("Surfaces", "1 humans"); }))
      << "human 4 left the messages but stayed:\n"
      << allStatuses();
  // Left out of the crowd message: gone once its last pose is drawn (the render delay, at most
  // 0.5 s), not frozen for the silent topic's timeout.
  const double left_after = (ros::WallTime::now() - dropped).toSec();
  EXPECT_LE(left_after, 0.5 + 0.2) << "human 4 stayed, frozen, after the message left it out";
  EXPECT_EQ(status("Model body_4"), nullptr);

  // Each bad message: the status names the human and what is wrong; human 3 stays drawn.
  struct Bad {
    std::string why;
    std::function<void(dressed_human::Crowd&)> spoil;
  };
  const std::vector<Bad> bad = {
      {"human '5': 47 joint angles, expected 48",
       [&](dressed_human::Crowd& m) {
         m.humans.push_back(human("5", 6.0));
         m.humans.back().joint_angles.resize(47);
       }},
      {"human '5': its root position is not finite",
       [&](dressed_human::Crowd& m) { m.humans.push_back(human("5", NAN)); }},
      {"human '5': joint angle 4 is not finite",
       [&](dressed_human::Crowd& m) {
         m.humans.push_back(human("5", 6.0));
         m.humans.back().joint_angles[4] = INFINITY;
       }},
      {"human '3' appears twice", [&](dressed_human::Crowd& m) { m.humans.push_back(human("3", 8.0)); }},
      {"human id 'a b' is not letters and digits",
       [&](dressed_human::Crowd& m) { m.humans.push_back(human("a b", 6.0)); }},
      {"frame 'nowhere' has no transform", [&](dressed_human::Crowd& m) { m.header.frame_id = "nowhere"; }},
  };
  for (const Bad& b : bad) {
    dressed_human::Crowd message = one;
    b.spoil(message);
    EXPECT_TRUE(runUntil(message, 5.0, [&] { return says("Crowd Message", b.why); }))
        << "not reported: " << b.why << "\n"
        << allStatuses();
    EXPECT_TRUE(says("Crowd Message", "'/test_crowd'")) << "the topic is not named:\n" << allStatuses();
    EXPECT_TRUE(says("Surfaces", "1 humans")) << b.why << "\n" << allStatuses();
    EXPECT_EQ(unexpectedErrors("Crowd Message"), "") << b.why;
  }
  ASSERT_TRUE(runUntil(one, 5.0, [&] { return status("Crowd Message") == nullptr; }))
      << "a clean message did not clear the error:\n"
      << allStatuses();
  EXPECT_TRUE(says("Surfaces", "1 humans")) << allStatuses();
  // The topic falls silent: its humans stay for the timeout (a late message is no departure),
  // then leave.
  const ros::WallTime silent = last_sent;
  const ros::WallTime deadline = silent + ros::WallDuration(3.0);
  while (!says("Humans", "0 from") && ros::WallTime::now() < deadline) frame();
  const double silent_for = (ros::WallTime::now() - silent).toSec();
  EXPECT_GE(silent_for, 0.9) << "human 3 left before the silent topic's second was up";
  EXPECT_LE(silent_for, 1.5) << "human 3 stayed more than a second after the topic fell silent:\n" << allStatuses();
  display_->subProp("Humans")->setValue("Robot Description");
  frames(5);
  EXPECT_EQ(status("Topic"), nullptr) << "the topic's status outlived From Topic";
}

// The Ogre objects under `node` that hold geometry (non-empty bounds), each with its bounds' size.
std::vector<std::pair<std::string, float>> drawnObjects(Ogre::SceneNode* node) {
  std::vector<std::pair<std::string, float>> objects;
  for (unsigned short i = 0; i < node->numAttachedObjects(); ++i) {
    const Ogre::MovableObject* object = node->getAttachedObject(i);
    if (!object->getBoundingBox().isNull() && !object->getBoundingBox().isInfinite())
      objects.emplace_back(object->getName(), object->getBoundingBox().getSize().length());
  }
  for (unsigned short i = 0; i < node->numChildren(); ++i) {
    if (auto* child = dynamic_cast<Ogre::SceneNode*>(node->getChild(i))) {
      for (auto& object : drawnObjects(child)) objects.push_back(object);
    }
  }
  std::sort(objects.begin(), objects.end());
  return objects;
}

// rviz resets every display when ROS time jumps back (each loop of a replayed bag) and on its
// Reset button: the human stays drawn through it, its Ogre objects and their geometry kept (a
// rebuild left it undrawn until its next frame, every loop of a replay).
TEST_F(DisplayLifecycleTest, ResetKeepsTheHumanDrawn) {
  ASSERT_NE(display_, nullptr) << "the dressed_human/DressedHuman plugin did not load";
  focusOnHuman();
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(60.0);
  while (!reported() && ros::WallTime::now() < deadline) frame();
  ASSERT_TRUE(reported()) << allStatuses();
  ASSERT_TRUE(drawnOnScreen()) << "not on screen before the reset\n" << allStatuses();
  frames(5);
  const auto before = drawnObjects(display_->getSceneNode());
  ASSERT_FALSE(before.empty()) << "no Ogre object with geometry under the display's scene node";
  display_->reset();
  EXPECT_EQ(drawnObjects(display_->getSceneNode()), before) << "the reset removed or emptied the human's geometry";
  EXPECT_TRUE(reported()) << allStatuses();
  EXPECT_TRUE(drawnOnScreen()) << "not on screen after the reset\n" << allStatuses();
  frames(5);
  EXPECT_EQ(unexpectedErrors(""), "");
  restoreView();
}

// Visible Ogre objects with geometry under `node`.
int visibleObjects(Ogre::SceneNode* node) {
  int visible = 0;
  for (unsigned short i = 0; i < node->numAttachedObjects(); ++i) {
    const Ogre::MovableObject* object = node->getAttachedObject(i);
    visible += object->getVisible() && !object->getBoundingBox().isNull() ? 1 : 0;
  }
  for (unsigned short i = 0; i < node->numChildren(); ++i) {
    if (auto* child = dynamic_cast<Ogre::SceneNode*>(node->getChild(i))) visible += visibleObjects(child);
  }
  return visible;
}

// A human outside the view is hidden and not updated (its mesh would be stale), and is drawn
// again as soon as the view comes back to it.
TEST_F(DisplayLifecycleTest, AHumanOutsideTheViewIsHiddenUntilItIsInViewAgain) {
  ASSERT_NE(display_, nullptr) << "the dressed_human/DressedHuman plugin did not load";
  focusOnHuman();
  frames(10);
  ASSERT_GT(visibleObjects(display_->getSceneNode()), 0) << allStatuses();
  rviz::ViewController* view = manager_->getViewManager()->getCurrent();
  view->subProp("Focal Point")->setValue(QVariant(QString("5000;5000;0")));
  frames(10);
  EXPECT_EQ(visibleObjects(display_->getSceneNode()), 0) << "a human far outside the view is still shown";
  focusOnHuman();
  frames(10);
  EXPECT_GT(visibleObjects(display_->getSceneNode()), 0) << "the human did not come back into view";
  EXPECT_EQ(unexpectedErrors(""), "");
  restoreView();
}

// rviz opened before the launch file: the robot description is not there yet. As RobotModelDisplay
// does, the display looks for it again every second and draws the human once it is set, without
// a reset; until then its URDF status names the parameter.
TEST_F(DisplayLifecycleTest, ADescriptionSetAfterTheDisplayStartedIsPickedUp) {
  ASSERT_NE(display_, nullptr) << "the dressed_human/DressedHuman plugin did not load";
  std::string description;
  ASSERT_TRUE(ros::param::get("robot_description", description));
  ros::param::del("late_robot_description");
  display_->subProp("Robot Description")->setValue("late_robot_description");
  frames(5);
  const rviz::StatusProperty* urdf = status("URDF");
  ASSERT_NE(urdf, nullptr) << allStatuses();
  EXPECT_EQ(urdf->getLevel(), rviz::StatusProperty::Error);
  EXPECT_NE(urdf->getValue().toString().toStdString().find("late_robot_description"), std::string::npos)
      << allStatuses();
  EXPECT_FALSE(drawnOnScreen()) << "a human drawn without a robot description";
  ros::param::set("late_robot_description", description);
  bool drawn = false;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(5.0);
  while (!drawn && ros::WallTime::now() < deadline) {
    ros::WallDuration(0.2).sleep();
    drawn = drawnOnScreen();
  }
  EXPECT_TRUE(drawn) << "the description set after the display started was not picked up\n" << allStatuses();
  EXPECT_EQ(status("URDF")->getLevel(), rviz::StatusProperty::Ok) << allStatuses();
  EXPECT_EQ(unexpectedErrors(""), "");
  display_->subProp("Robot Description")->setValue("robot_description");
  ros::param::del("late_robot_description");
  frames(5);
  restoreView();
}

// "Relief Strength" was renamed "Skin Relief Strength": a configuration saved before still sets
// it; where both are saved, the new key wins.
TEST_F(DisplayLifecycleTest, TheOldReliefStrengthKeyStillLoads) {
  ASSERT_NE(display_, nullptr) << "the dressed_human/DressedHuman plugin did not load";
  rviz::Config config;
  display_->save(config);
  config.mapRemoveChild("Skin Relief Strength");
  config.mapSetValue("Relief Strength", 2.5);
  display_->load(config);
  EXPECT_FLOAT_EQ(display_->subProp("Skin Relief Strength")->getValue().toFloat(), 2.5f);
  config.mapSetValue("Skin Relief Strength", 1.5);
  display_->load(config);
  EXPECT_FLOAT_EQ(display_->subProp("Skin Relief Strength")->getValue().toFloat(), 1.5f);
  frames(2);
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "display_lifecycle_test");
  QApplication application(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
