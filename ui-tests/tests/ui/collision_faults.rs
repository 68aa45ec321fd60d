use kinematics::Kinematics;

// A mesh whose file is not there: the error names the link, the file and where it was looked for.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../ui-tests/tests/ui/fixtures/missing_mesh.urdf", collision)]
struct Meshes;

// A mesh file that is no mesh: the error names the link and the file.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../ui-tests/tests/ui/fixtures/corrupt_mesh.urdf", collision)]
struct CorruptMesh;

// A sphere budget of zero.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5_spherized.urdf", collision(spheres = 0))]
struct NoSpheres;

// An SRDF naming a link the robot does not have.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5_spherized.urdf", collision(srdf = "../../../../ui-tests/tests/ui/fixtures/unknown_link.srdf"))]
struct UnknownSrdfLink;

// A cover that is no positive length.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5_spherized.urdf", collision(sphere_cover = -0.01))]
struct NegativeCover;

// A misspelt mesh policy.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", collision(meshes = "skp"))]
struct MisspeltMeshes;

// A negative radius: the model refuses the file, naming the link and the line.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../ui-tests/tests/ui/fixtures/negative_radius.urdf", collision)]
struct NegativeRadius;

fn main() {
    // The stub keeps the collision functions: no cascade.
    let _ = Meshes::collides(&[0.0; 1], &kinematics::collision::Environment::empty());
    let _ = CorruptMesh::self_collides(&[0.0; 1]);
    let _ = NoSpheres::sphere_centers(&[0.0; 6]);
    let _ = UnknownSrdfLink::self_collides(&[0.0; 6]);
    let _ = NegativeCover::sphere_centers(&[0.0; 6]);
}
