#include <cairn/multibody/plant/bullet_plant.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cairn/common/number_text.h>

namespace cairn::multibody {
namespace {

// Collision filter groups: the robot collides with the terrain only (no self-collision, no terrain-terrain pairs).
constexpr int kRobotGroup = 1 << 6;
constexpr int kTerrainGroup = 1 << 7;
// Bullet's default convex margin is 4 cm, more than half a 3 cm sole plate; boxes and cylinders keep their outer
// size and get 1 mm rounded edges instead.
constexpr double kShapeMargin = 1e-3;
// Allowed resting penetration (m).
constexpr double kLinearSlop = 1e-4;
// Bullet's joint-velocity clamp (default 100 rad/s) would be a hidden nonlinearity; this one is never reached by
// a robot.
constexpr double kMaxCoordinateVelocity = 1e6;

btVector3 ToBt(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }
Eigen::Vector3d FromBt(const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

btMatrix3x3 ToBt(const Eigen::Matrix3d& R) {
  return btMatrix3x3(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
}
Eigen::Matrix3d FromBt(const btMatrix3x3& M) {
  Eigen::Matrix3d R;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) R(r, c) = M[r][c];
  }
  return R;
}
btQuaternion ToBtQuaternion(const Eigen::Matrix3d& R) {
  const Eigen::Quaterniond q(R);
  return btQuaternion(q.x(), q.y(), q.z(), q.w());
}
btTransform ToBt(const Pose& X) { return btTransform(ToBt(X.rotation()), ToBt(X.translation())); }

// The Bullet frame of a merged body: at its centre of mass, along the principal axes of its inertia (Bullet wants a
// diagonal inertia), and the principal moments.
struct PrincipalFrame {
  Pose X_BL;
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();
  double mass = 0.0;
};

PrincipalFrame Principal(const SpatialInertia& inertia) {
  PrincipalFrame out;
  out.mass = inertia.mass();
  if (inertia.mass() <= 0.0) return out;
  const Eigen::Matrix3d I = inertia.InertiaAboutCom();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(0.5 * (I + I.transpose()));
  Eigen::Matrix3d R = solver.eigenvectors();
  if (R.determinant() < 0.0) R.col(2) = -R.col(2);
  out.X_BL = Pose(R, inertia.com());
  out.moments = solver.eigenvalues().cwiseMax(0.0);
  return out;
}

std::string BodyName(const Model& model, int body) { return "'" + model.body(body).name + "'"; }

void CheckFinite(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Index expected, const char* what) {
  if (x.size() != expected) {
    throw std::invalid_argument("BulletPlant: " + std::string(what) + " has size " + FormatShort(x.size()) +
                                ", but the model needs " + FormatShort(expected));
  }
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) {
      throw std::invalid_argument("BulletPlant: " + std::string(what) + "[" + FormatShort(i) + "] is " +
                                  FormatShort(x[i]) + "; every entry must be finite");
    }
  }
}

}  // namespace

struct BulletPlant::Impl {
  Impl(const Model& m, const std::vector<TerrainBox>& t, const BulletPlantOptions& o)
      : model(m), terrain(t), options(o) {}

  Model model;
  std::vector<TerrainBox> terrain;
  BulletPlantOptions options;
  bool floating = false;
  long long steps = 0;

  // Cairn body -> the moving body (or 0, the world, for a fixed base) it is merged into, and its pose there.
  std::vector<int> owner;
  std::vector<Pose> X_owner_body;
  // Cairn body -> Bullet link (-1: the base), for owners only; Bullet link -> Cairn body.
  std::vector<int> link_of_body;
  std::vector<int> body_of_link;
  // Bullet frame (centre of mass, principal axes) of each owner body in its own frame.
  std::vector<Pose> X_body_bullet;

  std::unique_ptr<btDefaultCollisionConfiguration> configuration;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::unique_ptr<btMultiBodyConstraintSolver> solver;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::unique_ptr<btMultiBody> multibody;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;
  std::vector<std::unique_ptr<btRigidBody>> terrain_bodies;
  std::unique_ptr<btMultiBodyDynamicsWorld> world;

  std::vector<ContactPoint> contacts;
  btAlignedObjectArray<btQuaternion> scratch_rotations;
  btAlignedObjectArray<btVector3> scratch_origins;

  ~Impl() {
    if (!world) return;
    for (auto& body : terrain_bodies) world->removeRigidBody(body.get());
    for (auto& collider : colliders) world->removeCollisionObject(collider.get());
    if (multibody) world->removeMultiBody(multibody.get());
    world.reset();
  }

  void BuildTree();
  void BuildMultiBody();
  void BuildColliders();
  void BuildTerrain();
  void ReadContacts();
};

void BulletPlant::Impl::BuildTree() {
  const int n = model.num_bodies();
  if (n < 2) throw std::invalid_argument("BulletPlant: model '" + model.name() + "' has no body besides the world");
  const JointType root_type = model.joint(1).type;
  floating = root_type == JointType::kFloating;
  owner.assign(static_cast<std::size_t>(n), 0);
  X_owner_body.assign(static_cast<std::size_t>(n), Pose());
  link_of_body.assign(static_cast<std::size_t>(n), -1);
  for (int b = 1; b < n; ++b) {
    const Joint& joint = model.joint(b);
    const int parent = joint.parent;
    if (joint.type == JointType::kFloating && b != 1) {
      throw std::invalid_argument("BulletPlant: body " + BodyName(model, b) + " has floating joint '" + joint.name +
                                  "'; only the root body (body 1) may float");
    }
    if (floating && b != 1 && parent == 0) {
      throw std::invalid_argument("BulletPlant: body " + BodyName(model, b) + " is attached to the world by joint '" +
                                  joint.name + "', but the floating base " + BodyName(model, 1) +
                                  " must be the only body attached to the world");
    }
    const std::size_t ub = static_cast<std::size_t>(b);
    if (joint.type == JointType::kFixed) {
      owner[ub] = owner[static_cast<std::size_t>(parent)];
      X_owner_body[ub] = X_owner_body[static_cast<std::size_t>(parent)] * joint.X_PJ;
    } else {
      owner[ub] = b;
    }
  }
  // Merged inertias, and the mass each owner carries including everything below it.
  std::vector<SpatialInertia> merged(static_cast<std::size_t>(n));
  for (int b = 1; b < n; ++b) {
    const std::size_t ub = static_cast<std::size_t>(b);
    merged[static_cast<std::size_t>(owner[ub])] += model.body(b).inertia.Transformed(X_owner_body[ub]);
  }
  std::vector<double> subtree_mass(static_cast<std::size_t>(n), 0.0);
  for (int b = n - 1; b >= 1; --b) {
    subtree_mass[static_cast<std::size_t>(b)] += model.body(b).inertia.mass();
    subtree_mass[static_cast<std::size_t>(model.parent(b))] += subtree_mass[static_cast<std::size_t>(b)];
  }
  X_body_bullet.assign(static_cast<std::size_t>(n), Pose());
  for (int b = 1; b < n; ++b) {
    const std::size_t ub = static_cast<std::size_t>(b);
    if (owner[ub] != b) continue;
    if (subtree_mass[ub] <= 0.0) {
      throw std::invalid_argument("BulletPlant: body " + BodyName(model, b) + " moves on joint '" +
                                  model.joint(b).name +
                                  "' but neither it nor any body below it has mass; Bullet's articulated-body "
                                  "algorithm needs mass behind every moving joint (give the link an <inertial>)");
    }
    X_body_bullet[ub] = Principal(merged[ub]).X_BL;
    if (b == 1 && floating && merged[ub].mass() <= 0.0) {
      throw std::invalid_argument("BulletPlant: the floating base " + BodyName(model, b) +
                                  " (with the bodies fixed to it) has no mass; give it an <inertial>");
    }
    if (b != 1 || !floating) {
      link_of_body[ub] = static_cast<int>(body_of_link.size());
      body_of_link.push_back(b);
    }
  }
}

void BulletPlant::Impl::BuildMultiBody() {
  const int num_links = static_cast<int>(body_of_link.size());
  btVector3 base_inertia(0.0, 0.0, 0.0);
  double base_mass = 0.0;
  if (floating) {
    SpatialInertia base;
    for (int b = 1; b < model.num_bodies(); ++b) {
      if (owner[static_cast<std::size_t>(b)] == 1) {
        base += model.body(b).inertia.Transformed(X_owner_body[static_cast<std::size_t>(b)]);
      }
    }
    const PrincipalFrame frame = Principal(base);
    base_mass = frame.mass;
    base_inertia = ToBt(frame.moments);
  }
  multibody = std::make_unique<btMultiBody>(num_links, base_mass, base_inertia, !floating, false);
  // The Bullet frame of each owner as a pose in its owner's frame; the fixed base's frame is the world's.
  auto bullet_frame = [&](int owner_body) { return owner_body == 0 ? Pose() : X_body_bullet[static_cast<std::size_t>(owner_body)]; };
  for (int k = 0; k < num_links; ++k) {
    const int b = body_of_link[static_cast<std::size_t>(k)];
    const Joint& joint = model.joint(b);
    const int parent_owner = owner[static_cast<std::size_t>(joint.parent)];
    const int parent_link = parent_owner == 0 ? -1 : link_of_body[static_cast<std::size_t>(parent_owner)];
    SpatialInertia merged;
    for (int c = 1; c < model.num_bodies(); ++c) {
      if (owner[static_cast<std::size_t>(c)] == b) {
        merged += model.body(c).inertia.Transformed(X_owner_body[static_cast<std::size_t>(c)]);
      }
    }
    const PrincipalFrame frame = Principal(merged);
    const Pose& X_BL = X_body_bullet[static_cast<std::size_t>(b)];
    // Child frame at zero motion in the parent owner's Bullet frame.
    const Pose X_parent_child = X_owner_body[static_cast<std::size_t>(joint.parent)] * joint.X_PJ;
    const Pose X_parentL_child = bullet_frame(parent_owner).Inverse() * X_parent_child;
    const Pose X_parentL_L = X_parentL_child * X_BL;
    const btQuaternion parent_to_this = ToBtQuaternion(X_parentL_L.rotation().transpose());
    const btVector3 parent_com_to_pivot = ToBt(X_parentL_child.translation());
    const btVector3 pivot_to_com = ToBt(Eigen::Vector3d(X_BL.rotation().transpose() * X_BL.translation()));
    const btVector3 axis = ToBt(Eigen::Vector3d(X_BL.rotation().transpose() * joint.axis));
    if (joint.type == JointType::kRevolute) {
      multibody->setupRevolute(k, frame.mass, ToBt(frame.moments), parent_link, parent_to_this, axis,
                               parent_com_to_pivot, pivot_to_com, true);
    } else {
      multibody->setupPrismatic(k, frame.mass, ToBt(frame.moments), parent_link, parent_to_this, axis,
                                parent_com_to_pivot, pivot_to_com, true);
    }
    multibody->getLink(k).m_jointDamping = 0.0;
    multibody->getLink(k).m_jointFriction = 0.0;
  }
  multibody->finalizeMultiDof();
  multibody->setLinearDamping(0.0);
  multibody->setAngularDamping(0.0);
  multibody->setMaxCoordinateVelocity(kMaxCoordinateVelocity);
  multibody->setUseGyroTerm(true);
  multibody->setHasSelfCollision(false);
  multibody->setCanSleep(false);
  world->addMultiBody(multibody.get(), kRobotGroup, kTerrainGroup);
}

void BulletPlant::Impl::BuildColliders() {
  const int n = model.num_bodies();
  // One compound shape per owner, holding the shapes of every body merged into it.
  for (int g = 0; g < n; ++g) {
    if (g != 0 && owner[static_cast<std::size_t>(g)] != g) continue;
    if (g == 0 && floating) continue;
    auto compound = std::make_unique<btCompoundShape>(false);
    const Pose X_L_owner = (g == 0 ? Pose() : X_body_bullet[static_cast<std::size_t>(g)]).Inverse();
    for (int b = 1; b < n; ++b) {
      if (owner[static_cast<std::size_t>(b)] != g) continue;
      for (const Geometry& geometry : model.body(b).collisions) {
        std::unique_ptr<btCollisionShape> shape;
        switch (geometry.type) {
          case GeometryType::kBox:
            shape = std::make_unique<btBoxShape>(ToBt(Eigen::Vector3d(0.5 * geometry.size)));
            break;
          case GeometryType::kSphere:
            shape = std::make_unique<btSphereShape>(geometry.radius);
            break;
          case GeometryType::kCylinder:
            shape = std::make_unique<btCylinderShapeZ>(btVector3(geometry.radius, geometry.radius,
                                                                 0.5 * geometry.length));
            break;
          case GeometryType::kCapsule:
            shape = std::make_unique<btCapsuleShapeZ>(geometry.radius, geometry.length);
            break;
          case GeometryType::kMesh:
            throw std::invalid_argument("BulletPlant: collision shape '" + geometry.name + "' of body " +
                                        BodyName(model, b) +
                                        " is a mesh, which the plant does not load; replace it by boxes, spheres, "
                                        "cylinders or capsules, or turn contacts off");
        }
        if (geometry.type == GeometryType::kBox || geometry.type == GeometryType::kCylinder) {
          shape->setMargin(kShapeMargin);
        }
        compound->addChildShape(ToBt(X_L_owner * X_owner_body[static_cast<std::size_t>(b)] * geometry.X_BG),
                                shape.get());
        shapes.push_back(std::move(shape));
      }
    }
    if (compound->getNumChildShapes() == 0) continue;
    const int link = g == 0 || (g == 1 && floating) ? -1 : link_of_body[static_cast<std::size_t>(g)];
    auto collider = std::make_unique<btMultiBodyLinkCollider>(multibody.get(), link);
    collider->setCollisionShape(compound.get());
    collider->setFriction(1.0);  // Bullet multiplies the two coefficients: the terrain's is the contact's.
    collider->setRestitution(0.0);
    collider->setActivationState(DISABLE_DEACTIVATION);
    world->addCollisionObject(collider.get(), kRobotGroup, kTerrainGroup);
    if (link < 0) {
      multibody->setBaseCollider(collider.get());
    } else {
      multibody->getLink(link).m_collider = collider.get();
    }
    shapes.push_back(std::move(compound));
    colliders.push_back(std::move(collider));
  }
}

void BulletPlant::Impl::BuildTerrain() {
  for (std::size_t i = 0; i < terrain.size(); ++i) {
    const TerrainBox& box = terrain[i];
    auto shape = std::make_unique<btBoxShape>(ToBt(Eigen::Vector3d(0.5 * box.size)));
    shape->setMargin(kShapeMargin);
    btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, shape.get());
    info.m_friction = box.friction;
    info.m_restitution = 0.0;
    auto body = std::make_unique<btRigidBody>(info);
    body->setWorldTransform(ToBt(box.X_WB));
    body->setUserIndex(static_cast<int>(i));
    if (std::isfinite(box.contact_stiffness)) body->setContactStiffnessAndDamping(box.contact_stiffness, box.contact_damping);
    world->addRigidBody(body.get(), kTerrainGroup, kRobotGroup);
    shapes.push_back(std::move(shape));
    terrain_bodies.push_back(std::move(body));
  }
}

void BulletPlant::Impl::ReadContacts() {
  contacts.clear();
  const double dt = options.time_step;
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    const btMultiBodyLinkCollider* robot_a = btMultiBodyLinkCollider::upcast(manifold->getBody0());
    const btMultiBodyLinkCollider* robot_b = btMultiBodyLinkCollider::upcast(manifold->getBody1());
    if ((robot_a == nullptr) == (robot_b == nullptr)) continue;
    const bool robot_is_a = robot_a != nullptr;
    const btMultiBodyLinkCollider* robot = robot_is_a ? robot_a : robot_b;
    const btCollisionObject* ground = robot_is_a ? manifold->getBody1() : manifold->getBody0();
    const int body = robot->m_link < 0 ? (floating ? 1 : 0) : body_of_link[static_cast<std::size_t>(robot->m_link)];
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      // Impulses act on body A along the normal (which points from B to A) and the friction directions.
      const double sign = robot_is_a ? 1.0 : -1.0;
      ContactPoint contact;
      contact.body = body;
      contact.terrain = ground->getUserIndex();
      contact.position = FromBt(robot_is_a ? point.getPositionWorldOnB() : point.getPositionWorldOnA());
      contact.normal = sign * FromBt(point.m_normalWorldOnB);
      contact.normal_force = point.m_appliedImpulse / dt;
      contact.tangential_force = sign *
                                 (point.m_appliedImpulseLateral1 * FromBt(point.m_lateralFrictionDir1) +
                                  point.m_appliedImpulseLateral2 * FromBt(point.m_lateralFrictionDir2)) /
                                 dt;
      contact.distance = point.getDistance();
      contacts.push_back(contact);
    }
  }
}

BulletPlant::BulletPlant(const Model& model, const std::vector<TerrainBox>& terrain, const BulletPlantOptions& options)
    : impl_(std::make_unique<Impl>(model, terrain, options)) {
  if (!(options.time_step > 0.0 && options.time_step <= BulletPlantOptions::kMaxTimeStep)) {
    throw std::invalid_argument("BulletPlant: time_step " + FormatShort(options.time_step) +
                                " s is outside (0, " + FormatShort(BulletPlantOptions::kMaxTimeStep) + "] s");
  }
  if (options.solver_iterations < 1 || options.solver_iterations > BulletPlantOptions::kMaxSolverIterations) {
    throw std::invalid_argument("BulletPlant: solver_iterations " + FormatShort(options.solver_iterations) +
                                " is outside [1, " + FormatShort(BulletPlantOptions::kMaxSolverIterations) + "]");
  }
  if (terrain.size() > static_cast<std::size_t>(kMaxTerrainBoxes)) {
    throw std::invalid_argument("BulletPlant: " + FormatShort(terrain.size()) + " terrain boxes exceed the limit of " +
                                FormatShort(kMaxTerrainBoxes));
  }
  for (const TerrainBox& box : terrain) {
    for (int a = 0; a < 3; ++a) {
      if (!(std::isfinite(box.size[a]) && box.size[a] > 0.0)) {
        throw std::invalid_argument("BulletPlant: terrain box '" + box.name + "' has size[" + FormatShort(a) +
                                    "] = " + FormatShort(box.size[a]) + "; sizes must be finite and > 0");
      }
    }
    if (!(box.friction >= 0.0 && box.friction <= 10.0)) {
      throw std::invalid_argument("BulletPlant: terrain box '" + box.name + "' has friction " +
                                  FormatShort(box.friction) + "; it must lie in [0, 10]");
    }
    if (!(box.contact_stiffness > 0.0)) {
      throw std::invalid_argument("BulletPlant: terrain box '" + box.name + "' has contact_stiffness " +
                                  FormatShort(box.contact_stiffness) +
                                  " N/m; it must be > 0 (infinity, the default, is rigid)");
    }
    if (!(std::isfinite(box.contact_damping) && box.contact_damping >= 0.0)) {
      throw std::invalid_argument("BulletPlant: terrain box '" + box.name + "' has contact_damping " +
                                  FormatShort(box.contact_damping) + " N s/m; it must be finite and >= 0");
    }
    if (std::isinf(box.contact_stiffness) && box.contact_damping > 0.0) {
      throw std::invalid_argument("BulletPlant: terrain box '" + box.name + "' has contact_damping " +
                                  FormatShort(box.contact_damping) +
                                  " N s/m but a rigid contact; give it a finite contact_stiffness or damping 0");
    }
    if (!box.X_WB.translation().allFinite() || !box.X_WB.rotation().allFinite()) {
      throw std::invalid_argument("BulletPlant: terrain box '" + box.name + "' has a non-finite pose");
    }
  }
  Impl& s = *impl_;
  s.BuildTree();
  s.configuration = std::make_unique<btDefaultCollisionConfiguration>();
  s.dispatcher = std::make_unique<btCollisionDispatcher>(s.configuration.get());
  s.broadphase = std::make_unique<btDbvtBroadphase>();
  s.solver = std::make_unique<btMultiBodyConstraintSolver>();
  s.world = std::make_unique<btMultiBodyDynamicsWorld>(s.dispatcher.get(), s.broadphase.get(), s.solver.get(),
                                                       s.configuration.get());
  s.world->setGravity(ToBt(model.gravity()));
  btContactSolverInfo& info = s.world->getSolverInfo();
  info.m_numIterations = options.solver_iterations;
  // Two friction directions per contact: with one, a resting contact is held along one arbitrary direction only.
  info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
  // Resting contacts settle kLinearSlop deep instead of at zero depth, where Bullet's box-box detector drops a
  // sole's contacts for a step now and then (the foot then falls a few micrometres and is caught by a doubled
  // impulse on the next step).
  info.m_linearSlop = kLinearSlop;
  s.BuildMultiBody();
  if (options.contacts) {
    s.BuildColliders();
    s.BuildTerrain();
  }
  Eigen::VectorXd q = Eigen::VectorXd::Zero(model.nq());
  if (s.floating) q[model.joint(1).idx_q + 3] = 1.0;
  SetState(q, Eigen::VectorXd::Zero(model.nv()));
}

BulletPlant::~BulletPlant() = default;

const Model& BulletPlant::model() const { return impl_->model; }
const std::vector<TerrainBox>& BulletPlant::terrain() const { return impl_->terrain; }
const BulletPlantOptions& BulletPlant::options() const { return impl_->options; }
int BulletPlant::num_links() const { return static_cast<int>(impl_->body_of_link.size()); }
int BulletPlant::merged_body(int body) const {
  if (body < 0 || body >= impl_->model.num_bodies()) {
    throw std::invalid_argument("BulletPlant: body index " + FormatShort(body) + " is outside [0, " +
                                FormatShort(impl_->model.num_bodies() - 1) + "]");
  }
  return impl_->owner[static_cast<std::size_t>(body)];
}
double BulletPlant::time() const { return static_cast<double>(impl_->steps) * impl_->options.time_step; }
const std::vector<ContactPoint>& BulletPlant::contacts() const { return impl_->contacts; }

void BulletPlant::SetState(const Eigen::Ref<const Eigen::VectorXd>& q, const Eigen::Ref<const Eigen::VectorXd>& v) {
  Impl& s = *impl_;
  CheckFinite(q, s.model.nq(), "q");
  CheckFinite(v, s.model.nv(), "v");
  btMultiBody& mb = *s.multibody;
  if (s.floating) {
    const Joint& root = s.model.joint(1);
    Eigen::Quaterniond quaternion(q[root.idx_q + 3], q[root.idx_q + 4], q[root.idx_q + 5], q[root.idx_q + 6]);
    if (!(quaternion.norm() > 1e-12)) {
      throw std::invalid_argument("BulletPlant: the floating base quaternion in q is zero; it must be a unit quaternion");
    }
    quaternion.normalize();
    const Pose X_WB(quaternion.toRotationMatrix(), q.segment<3>(root.idx_q));
    const Pose& X_BL = s.X_body_bullet[1];
    mb.setBaseWorldTransform(ToBt(X_WB * X_BL));
    const Eigen::Vector3d w_B = v.segment<3>(root.idx_v);
    const Eigen::Vector3d v_B = v.segment<3>(root.idx_v + 3);
    mb.setBaseOmega(ToBt(Eigen::Vector3d(X_WB.rotation() * w_B)));
    mb.setBaseVel(ToBt(Eigen::Vector3d(X_WB.rotation() * (v_B + w_B.cross(X_BL.translation())))));
  }
  for (std::size_t k = 0; k < s.body_of_link.size(); ++k) {
    const Joint& joint = s.model.joint(s.body_of_link[k]);
    mb.setJointPos(static_cast<int>(k), q[joint.idx_q]);
    mb.setJointVel(static_cast<int>(k), v[joint.idx_v]);
  }
  mb.updateCollisionObjectWorldTransforms(s.scratch_rotations, s.scratch_origins);
}

Eigen::VectorXd BulletPlant::positions() const {
  const Impl& s = *impl_;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(s.model.nq());
  const btMultiBody& mb = *s.multibody;
  if (s.floating) {
    const Joint& root = s.model.joint(1);
    const btTransform X = mb.getBaseWorldTransform();
    const Pose X_WB = Pose(FromBt(X.getBasis()), FromBt(X.getOrigin())) * s.X_body_bullet[1].Inverse();
    q.segment<3>(root.idx_q) = X_WB.translation();
    Eigen::Quaterniond quaternion(X_WB.rotation());
    quaternion.normalize();
    q[root.idx_q + 3] = quaternion.w();
    q[root.idx_q + 4] = quaternion.x();
    q[root.idx_q + 5] = quaternion.y();
    q[root.idx_q + 6] = quaternion.z();
  }
  for (std::size_t k = 0; k < s.body_of_link.size(); ++k) {
    q[s.model.joint(s.body_of_link[k]).idx_q] = mb.getJointPos(static_cast<int>(k));
  }
  return q;
}

Eigen::VectorXd BulletPlant::velocities() const {
  const Impl& s = *impl_;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(s.model.nv());
  const btMultiBody& mb = *s.multibody;
  if (s.floating) {
    const Joint& root = s.model.joint(1);
    const Eigen::Matrix3d R_WB = FromBt(mb.getBaseWorldTransform().getBasis()) * s.X_body_bullet[1].rotation().transpose();
    const Eigen::Vector3d w_B = R_WB.transpose() * FromBt(mb.getBaseOmega());
    const Eigen::Vector3d v_B = R_WB.transpose() * FromBt(mb.getBaseVel()) - w_B.cross(s.X_body_bullet[1].translation());
    v.segment<3>(root.idx_v) = w_B;
    v.segment<3>(root.idx_v + 3) = v_B;
  }
  for (std::size_t k = 0; k < s.body_of_link.size(); ++k) {
    v[s.model.joint(s.body_of_link[k]).idx_v] = mb.getJointVel(static_cast<int>(k));
  }
  return v;
}

void BulletPlant::Step(const Eigen::Ref<const Eigen::VectorXd>& tau) {
  Impl& s = *impl_;
  CheckFinite(tau, s.model.nv(), "tau");
  btMultiBody& mb = *s.multibody;
  mb.clearForcesAndTorques();
  if (s.floating) {
    const Joint& root = s.model.joint(1);
    const Pose& X_BL = s.X_body_bullet[1];
    const Eigen::Matrix3d R_WB = FromBt(mb.getBaseWorldTransform().getBasis()) * X_BL.rotation().transpose();
    const Eigen::Vector3d n_B = tau.segment<3>(root.idx_v);
    const Eigen::Vector3d f_B = tau.segment<3>(root.idx_v + 3);
    // The same wrench about the centre of mass, where Bullet applies base forces.
    mb.addBaseForce(ToBt(Eigen::Vector3d(R_WB * f_B)));
    mb.addBaseTorque(ToBt(Eigen::Vector3d(R_WB * (n_B - X_BL.translation().cross(f_B)))));
  }
  for (std::size_t k = 0; k < s.body_of_link.size(); ++k) {
    mb.addJointTorque(static_cast<int>(k), tau[s.model.joint(s.body_of_link[k]).idx_v]);
  }
  s.world->stepSimulation(s.options.time_step, 0, s.options.time_step);
  ++s.steps;
  s.ReadContacts();
}

}  // namespace cairn::multibody
