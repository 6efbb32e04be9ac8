"""Findings of benchmarks/engines.py (docs/testing_engines.md): each function rebuilds the tree
of one case (its number in the list the command draws); the comments say what was found."""

from isocsg import *  # noqa: F403


# case 4, pyvista: crashed (exit code -11)
def case_4():
    p0 = Ellipsoid(center=(0.25, 0.0, 0.0), radii=(0.25, 0.25, 0.25))
    p1 = Sphere(center=(0.0, 0.0, 0.0), radius=0.25)
    n2 = Union(p0, p1)
    p3 = Sphere(center=(0.0, 0.0, 0.0), radius=0.25)
    n4 = Union(n2, p3)
    p5 = Sphere(center=(0.0, 0.0, 0.0), radius=0.25)
    n6 = Union(n4, p5)
    p7 = Sphere(center=(0.0, 0.0, 0.0), radius=0.25)
    tree = Union(n6, p7)
    return tree


# case 9, pyvista: wrong topology
# volume    0.568267441 (true 0.605147921): error -3.688e-02, tessellation -3.488e-02, bound 5.231e-01 -> tessellation
# area      5.54661425 (true 5.80089268): error -2.543e-01, tessellation -2.525e-01 -> tessellation
# hausdorff mesh->true 1.504e-02, true->mesh 1.792e-02, tessellation 1.237e-02 -> tessellation
# topology  3 components, genus 3, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_9():
    p0 = Torus(center=(-1.0, -0.5, 0.0), axis=(0.0, 0.0, 1.0), major=2.25, minor=0.45)
    p1 = Torus(center=(0.0, 0.25, 0.0), axis=(0.0, 1.0, 0.0), major=1.0, minor=0.35)
    n2 = Union(p0, p1)
    p3 = Torus(center=(-0.25, -0.5, 0.75), axis=(0.0, 1.0, 0.0), major=1.5, minor=0.5249999999999999)
    tree = Intersection(n2, p3)
    return tree


# case 10, trimesh-manifold: wrong topology
# volume    1.75275072 (true 1.8387974): error -8.605e-02, tessellation -8.605e-02, bound 5.231e-01 -> tessellation
# area      14.6417353 (true 14.8619221): error -2.202e-01, tessellation -2.202e-01 -> tessellation
# hausdorff mesh->true 1.217e-02, true->mesh 1.110e-02, tessellation 1.110e-02 -> tessellation
# topology  75 components, genus 38, watertight False, winding consistent False (true: 1, genus 1) -> wrong
# verdict   WRONG: topology
# case 10, pyvista: wrong topology
# volume    1.75274923 (true 1.8387974): error -8.605e-02, tessellation -8.605e-02, bound 5.231e-01 -> tessellation
# area      14.6417347 (true 14.8619221): error -2.202e-01, tessellation -2.202e-01 -> tessellation
# hausdorff mesh->true 1.203e-02, true->mesh 1.110e-02, tessellation 1.110e-02 -> tessellation
# topology  2 components, genus 2.5, watertight False, winding consistent False (true: 1, genus 1) -> wrong
# verdict   WRONG: topology
def case_10():
    p0 = Torus(center=(-1.0, -0.5, 0.0), axis=(0.0, 0.0, 1.0), major=2.25, minor=0.45)
    p1 = Torus(center=(-0.25, -0.5, 0.75), axis=(0.0, 1.0, 0.0), major=1.0, minor=0.35)
    n2 = Union(p0, p1)
    p3 = Torus(center=(-0.25, -0.5, 0.75), axis=(0.0, 1.0, 0.0), major=1.5, minor=0.5249999999999999)
    tree = Intersection(n2, p3)
    return tree


# case 11, pyvista: wrong topology
# volume    0.493004641 (true 0.530972024): error -3.797e-02, tessellation -3.996e-02, bound 3.712e-01 -> tessellation
# area      8.38797994 (true 8.64667099): error -2.587e-01, tessellation -2.565e-01 -> tessellation
# hausdorff mesh->true 8.775e-03, true->mesh 8.313e-03, tessellation 8.683e-03 -> tessellation
# topology  1 components, genus 2, watertight False, winding consistent False (true: 1, genus 1) -> wrong
# verdict   WRONG: topology
def case_11():
    p0 = Torus(center=(-1.0, -0.5, 0.0), axis=(0.0, 0.0, 1.0), major=2.25, minor=0.45)
    p1 = Torus(center=(-0.25, -0.5, 0.75), axis=(0.0, 1.0, 0.0), major=1.0, minor=0.35)
    n2 = Union(p0, p1)
    p3 = Torus(center=(-0.25, -0.5, 0.75), axis=(0.0, 1.0, 0.0), major=1.5, minor=0.30000000000000004)
    tree = Intersection(n2, p3)
    return tree


# case 12, trimesh-manifold: wrong topology
# volume    2.35235017 (true 2.41805308): error -6.570e-02, tessellation -6.570e-02, bound 3.670e-01 -> tessellation
# area      13.7141535 (true 13.8174462): error -1.033e-01, tessellation -1.033e-01 -> tessellation
# hausdorff mesh->true 8.325e-03, true->mesh 8.362e-03, tessellation 8.362e-03 -> tessellation
# topology  2 components, genus 1.5, watertight False, winding consistent False (true: 1, genus 1, from mesh) -> wrong
# verdict   WRONG: topology
# case 12, pyvista: crashed (exit code -11)
def case_12():
    p0 = Torus(center=(-1.0, -0.5, 0.0), axis=(0.0, 0.0, 1.0), major=2.25, minor=0.45)
    p1 = Torus(center=(-0.25, -0.5, 0.75), axis=(0.0, 1.0, 0.0), major=1.0, minor=0.35)
    n2 = Union(p0, p1)
    p3 = Torus(center=(-0.25, -0.5, 0.75), axis=(0.0, 1.0, 0.0), major=1.0, minor=0.35)
    tree = Intersection(n2, p3)
    return tree


# case 30, pyvista: wrong topology
# volume    3.83962281 (true 3.9269626): error -8.734e-02, tessellation -8.775e-02, bound 8.772e-02 -> tessellation
# area      15.5056679 (true 15.6890661): error -1.834e-01, tessellation -1.851e-01 -> tessellation
# hausdorff mesh->true 1.340e-02, true->mesh 1.378e-02, tessellation 1.378e-02 -> tessellation
# topology  3 components, genus 4.5, watertight False, winding consistent False (true: 1, genus 2) -> wrong
# verdict   WRONG: topology
def case_30():
    p0 = Ellipsoid(center=(1.0, 0.25, 0.25), radii=(1.5, 0.5, 1.25))
    p1 = Box(center=(1.0, 0.0, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(p0, p1)
    return tree


# case 31, pyvista: wrong hausdorff, topology
# volume    3.84058954 (true 3.92701181): error -8.642e-02, tessellation -8.778e-02, bound 8.772e-02 -> tessellation
# area      15.6625989 (true 15.4358138): error +2.268e-01, tessellation -1.984e-01 -> tessellation
# hausdorff mesh->true 4.867e-01, true->mesh 1.146e-02, tessellation 1.278e-02 -> wrong
# topology  3 components, genus 2, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: hausdorff, topology
def case_31():
    p0 = Ellipsoid(center=(0.5, 0.25, 0.25), radii=(1.5, 0.5, 1.25))
    p1 = Box(center=(1.0, 0.0, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(p0, p1)
    return tree


# case 32, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 3.92699082): error -3.927e+00, tessellation -8.772e-02, bound 8.772e-02 -> wrong
# area      0 (true 14.621119): error -1.462e+01, tessellation -1.701e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.199e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_32():
    p0 = Ellipsoid(center=(0.5, 0.25, 1.0), radii=(1.5, 0.5, 1.25))
    p1 = Box(center=(1.0, 0.0, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(p0, p1)
    return tree


# case 34, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000100016594 (true 0.0001): error +1.659e-08, tessellation -7.345e-18, bound 2.204e-17 -> wrong
# area      2.00040007 (true 2.0004): error +6.638e-08, tessellation -4.441e-16 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
# case 34, pyvista: wrong volume, area, hausdorff
# volume    0.000100016594 (true 0.0001): error +1.659e-08, tessellation -7.345e-18, bound 2.204e-17 -> wrong
# area      2.00040007 (true 2.0004): error +6.638e-08, tessellation -4.441e-16 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_34():
    p0 = Box(center=(1.0, 0.0, -0.75), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(1.0, 1.0, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(p0, p1)
    return tree


# case 37, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 6.47068769): error -6.471e+00, tessellation -1.601e-01, bound 1.857e-01 -> wrong
# area      0 (true 33.325245): error -3.333e+01, tessellation -5.354e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.931e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 1) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_37():
    p0 = Ellipsoid(center=(-0.25, 0.5, 0.25), radii=(1.25, 0.75, 2.0))
    p1 = Cone(center=(-0.25, 0.0, 0.25), axis=(0.0, 0.5, 0.0), radius=1.75)
    tree = Difference(p0, p1)
    return tree


# case 43, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.261799388): error -2.618e-01, tessellation -5.848e-03, bound 8.772e-03 -> wrong
# area      0 (true 2.16797068): error -2.168e+00, tessellation -2.584e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 5.119e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_43():
    p0 = Ellipsoid(center=(-0.25, 0.5, 0.0), radii=(0.25, 0.5, 0.5))
    p1 = Ellipsoid(center=(0.25, 0.5, 0.0), radii=(0.25, 0.5, 0.25))
    tree = Difference(p0, p1)
    return tree


# case 45, pyvista: wrong volume, area, hausdorff, topology
# volume    1.46186514 (true 1.36287894): error +9.899e-02, tessellation +3.191e-04, bound 1.028e-02 -> wrong
# area      12.1263952 (true 11.2460263): error +8.804e-01, tessellation -3.144e-03 -> wrong
# hausdorff mesh->true 5.000e-01, true->mesh 2.201e-03, tessellation 2.201e-03 -> wrong
# topology  5 components, genus 8.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_45():
    p0 = Box(center=(0.37499999999999994, -0.649519052838329, 0.25), size=(0.5, 1.5, 2.0), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(-0.7071067811865476, -0.7071067811865475, -0.75), size=(1.75, 1.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.75, -0.5, 0.25), size=(1.0, 1.0, 0.0001))
    n4 = Union(n2, p3)
    p5 = Cone(center=(0.5, 1.0, -0.75), axis=(0.0, 0.0, 0.5), radius=1.75)
    tree = Difference(n4, p5)
    return tree


# case 46, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_46():
    p0 = Box(center=(-0.7071067811865476, -0.7071067811865475, -0.75), size=(1.75, 1.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(-0.7071067811865476, -0.7071067811865475, -0.75), size=(1.75, 1.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.75, -0.5, 0.25), size=(1.0, 1.0, 0.0001))
    n4 = Union(n2, p3)
    p5 = Cone(center=(0.5, 1.0, -0.75), axis=(0.0, 0.0, 0.5), radius=1.75)
    tree = Difference(n4, p5)
    return tree


# case 47, trimesh-manifold: wrong volume, area, hausdorff
# volume    2.77911784 (true 2.578225): error +2.009e-01, tessellation +7.550e-15, bound 1.028e-02 -> wrong
# area      16.2130293 (true 14.2504): error +1.963e+00, tessellation +9.730e-01 -> wrong
# hausdorff mesh->true 4.297e-01, true->mesh 1.412e-01, tessellation 3.331e-16 -> wrong
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_47():
    p0 = Box(center=(-0.7071067811865476, -0.7071067811865475, -0.75), size=(1.75, 1.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.0, 0.0, 0.0), size=(1.75, 1.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.75, -0.5, 0.25), size=(1.0, 1.0, 0.0001))
    n4 = Union(n2, p3)
    p5 = Cone(center=(0.5, 1.0, -0.75), axis=(0.0, 0.0, 0.5), radius=1.75)
    tree = Difference(n4, p5)
    return tree


# case 48, trimesh-manifold: wrong area, hausdorff
# volume    0.515724951 (true 0.515725): error -4.888e-08, tessellation +1.665e-15, bound 1.028e-02 -> tessellation
# area      7.75039987 (true 7.7504): error -1.277e-07, tessellation +1.776e-14 -> wrong
# hausdorff mesh->true 3.301e-08, true->mesh 3.370e-08, tessellation 3.140e-16 -> wrong
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: area, hausdorff
def case_48():
    p0 = Box(center=(-0.7071067811865476, -0.7071067811865475, -0.75), size=(1.75, 0.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.0, 0.0, 0.0), size=(1.75, 1.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.75, -0.5, 0.25), size=(1.0, 1.0, 0.0001))
    n4 = Union(n2, p3)
    p5 = Cone(center=(0.5, 1.0, -0.75), axis=(0.0, 0.0, 0.5), radius=1.75)
    tree = Difference(n4, p5)
    return tree


# case 49, trimesh-manifold: wrong area, hausdorff
# volume    0.515724951 (true 0.515725): error -4.888e-08, tessellation -2.605e-13, bound 2.099e-04 -> tessellation
# area      7.75039987 (true 7.7504): error -1.277e-07, tessellation -9.042e-13 -> wrong
# hausdorff mesh->true 3.370e-08, true->mesh 3.357e-08, tessellation 5.551e-16 -> wrong
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: area, hausdorff
def case_49():
    p0 = Box(center=(-0.7071067811865476, -0.7071067811865475, -0.75), size=(1.75, 0.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.0, 0.0, 0.0), size=(1.75, 1.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.75, -0.5, 0.25), size=(1.0, 1.0, 0.0001))
    n4 = Union(n2, p3)
    p5 = Cone(center=(0.5, 1.0, -0.75), axis=(0.0, 0.0, 0.5), radius=0.25)
    tree = Difference(n4, p5)
    return tree


# case 50, trimesh-manifold: wrong area, hausdorff
# volume    0.515724951 (true 0.515725): error -4.888e-08, tessellation -2.605e-13, bound 2.099e-04 -> tessellation
# area      7.75039987 (true 7.7504): error -1.277e-07, tessellation -9.042e-13 -> wrong
# hausdorff mesh->true 3.357e-08, true->mesh 3.360e-08, tessellation 3.140e-16 -> wrong
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: area, hausdorff
def case_50():
    p0 = Box(center=(-0.7071067811865476, -0.7071067811865475, -0.75), size=(1.75, 0.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.0, 0.0, 0.0), size=(1.75, 1.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.75, -0.5, 0.25), size=(1.0, 1.0, 0.0001))
    n4 = Union(n2, p3)
    p5 = Cone(center=(0.5, 1.0, -0.5), axis=(0.0, 0.0, 0.5), radius=0.25)
    tree = Difference(n4, p5)
    return tree


# case 51, trimesh-manifold: wrong hausdorff
# volume    3.7962367 (true 3.79615016): error +8.653e-05, tessellation +8.689e-05, bound 2.099e-04 -> exact
# area      19.9929605 (true 19.993199): error -2.384e-04, tessellation -2.375e-04 -> exact
# hausdorff mesh->true 4.581e-08, true->mesh 4.459e-08, tessellation 3.140e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: hausdorff
# case 51, pyvista: wrong volume, area, hausdorff, topology
# volume    3.79742051 (true 3.79615016): error +1.270e-03, tessellation +8.689e-05, bound 2.099e-04 -> wrong
# area      20.1205107 (true 19.993199): error +1.273e-01, tessellation -2.375e-04 -> wrong
# hausdorff mesh->true 7.675e-04, true->mesh 8.565e-02, tessellation 3.140e-16 -> wrong
# topology  1 components, genus 1, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_51():
    p0 = Box(center=(-0.7071067811865476, -0.7071067811865475, -0.75), size=(1.75, 0.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.0, 0.0, 0.0), size=(1.75, 1.25, 1.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Union(p0, p1)
    p3 = Box(center=(0.75, -0.5, 0.25), size=(1.0, 1.0, 0.0001))
    n4 = Union(n2, p3)
    p5 = Cone(center=(0.5, 1.0, -0.5), axis=(0.0, 0.0, 0.5), radius=0.25)
    tree = Difference(n4, p5)
    return tree


# case 52, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_52():
    p0 = Cylinder(center=(-0.75, 0.75, -1.0), axis=(0.22499999999999998, -0.375, 0.75), radius=0.25)
    p1 = Truncus(center=(-0.25, 0.75, 0.0), axis=(0.075, -0.125, 0.25), r1=1.5, r2=0.5)
    p2 = Cylinder(center=(-0.5, -0.5, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Difference(p1, p2)
    n4 = Intersection(p0, n3)
    p5 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Union(n4, p5)
    return tree


# case 53, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_53():
    p0 = Cylinder(center=(-0.75, 0.75, -1.0), axis=(0.22499999999999998, -0.375, 0.75), radius=0.25)
    p1 = Truncus(center=(-0.25, 0.75, 0.0), axis=(0.075, -0.125, 0.25), r1=0.25, r2=0.5)
    p2 = Cylinder(center=(-0.5, -0.5, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Difference(p1, p2)
    n4 = Intersection(p0, n3)
    p5 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Union(n4, p5)
    return tree


# case 54, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_54():
    p0 = Cylinder(center=(-0.75, 0.75, -1.0), axis=(0.22499999999999998, -0.375, 0.75), radius=0.25)
    p1 = Truncus(center=(-0.25, 0.75, 0.0), axis=(0.075, -0.125, 0.25), r1=0.25, r2=0.25)
    p2 = Cylinder(center=(-0.5, -0.5, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Difference(p1, p2)
    n4 = Intersection(p0, n3)
    p5 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Union(n4, p5)
    return tree


# case 55, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_55():
    p0 = Cylinder(center=(-0.75, 0.75, -1.0), axis=(0.22499999999999998, -0.375, 0.75), radius=0.25)
    p1 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    p2 = Cylinder(center=(-0.5, -0.5, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Difference(p1, p2)
    n4 = Intersection(p0, n3)
    p5 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Union(n4, p5)
    return tree


# case 56, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_56():
    p0 = Cylinder(center=(-0.75, -0.5, -1.0), axis=(0.22499999999999998, -0.375, 0.75), radius=0.25)
    p1 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    p2 = Cylinder(center=(-0.5, -0.5, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Difference(p1, p2)
    n4 = Intersection(p0, n3)
    p5 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Union(n4, p5)
    return tree


# case 57, trimesh-manifold: wrong hausdorff
# volume    3.65575506e-06 (true 3.72610707e-06): error -7.035e-08, tessellation -7.036e-08, bound 1.098e-03 -> tessellation
# area      0.00752308852 (true 0.00765975999): error -1.367e-04, tessellation -1.367e-04 -> tessellation
# hausdorff mesh->true 4.115e-04, true->mesh 1.170e-04, tessellation 2.404e-04 -> wrong
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> exact
# verdict   WRONG: hausdorff
def case_57():
    p0 = Cylinder(center=(-0.75, -0.5, -1.0), axis=(0.22499999999999998, -0.375, 0.75), radius=0.25)
    p1 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(-0.5, -0.5, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n4 = Intersection(n2, p3)
    p5 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Union(n4, p5)
    return tree


# case 59, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.17809725): error -1.178e+00, tessellation -2.632e-02, bound 6.568e-02 -> wrong
# area      0 (true 8.07059776): error -8.071e+00, tessellation -9.044e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.072e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_59():
    p0 = Ellipsoid(center=(-0.75, 0.25, -0.75), radii=(1.5, 0.25, 0.75))
    p1 = Cylinder(center=(0.0, -1.0, 0.25), axis=(0.22499999999999998, -0.375, 0.75), radius=1.5)
    p2 = Cylinder(center=(0.75, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Difference(p1, p2)
    tree = Difference(p0, n3)
    return tree


# case 60, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.734041629): error -7.340e-01, tessellation -1.803e-02, bound 6.568e-02 -> wrong
# area      0 (true 7.4390439): error -7.439e+00, tessellation -8.386e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 9.138e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 1) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_60():
    p0 = Ellipsoid(center=(0.75, -0.25, 0.0), radii=(1.5, 0.25, 0.75))
    p1 = Cylinder(center=(0.0, -1.0, 0.25), axis=(0.22499999999999998, -0.375, 0.75), radius=1.5)
    p2 = Cylinder(center=(0.75, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Difference(p1, p2)
    tree = Difference(p0, n3)
    return tree


# case 61, pyvista: hung over 120 s
def case_61():
    p0 = Ellipsoid(center=(0.75, -0.25, 0.0), radii=(1.5, 0.25, 0.75))
    p1 = Cylinder(center=(0.25, -1.0, 0.25), axis=(0.22499999999999998, -0.375, 0.75), radius=1.5)
    p2 = Cylinder(center=(0.75, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Difference(p1, p2)
    tree = Difference(p0, n3)
    return tree


# case 64, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_64():
    p0 = Truncus(center=(1.0, 1.0, 0.75), axis=(0.75, 0.0, 0.0), r1=1.0, r2=1.0)
    p1 = Cone(center=(-1.0, -0.5, 0.25), axis=(0.375, -0.625, 1.25), radius=1.5)
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.5, 1.0, -1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Difference(n2, p3)
    return tree


# case 68, trimesh-manifold: wrong area, hausdorff
# volume    0.000100016594 (true 0.0001): error +1.659e-08, tessellation -4.167e-17, bound 2.718e-02 -> tessellation
# area      2.00040007 (true 2.0004): error +6.638e-08, tessellation +6.661e-15 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: area, hausdorff
def case_68():
    p0 = Box(center=(0.0, 0.0, 0.5), size=(1.0, 1.0, 0.0001))
    p1 = Truncus(center=(1.0, 1.0, -0.5), axis=(1.75, 0.0, 0.0), r1=0.75, r2=1.0)
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.21650635094610968, 0.12499999999999999, -0.75), size=(0.75, 0.75, 0.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n2, p3)
    return tree


# case 69, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000100016594 (true 0.0001): error +1.659e-08, tessellation -1.102e-17, bound 2.331e-16 -> wrong
# area      2.00040007 (true 2.0004): error +6.638e-08, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_69():
    p0 = Box(center=(0.0, 0.0, 0.5), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.6639330512402987, 1.2486764606857723, -0.5), size=(0.5, 1.75, 0.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.21650635094610968, 0.12499999999999999, -0.75), size=(0.75, 0.75, 0.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n2, p3)
    return tree


# case 72, trimesh-manifold: wrong volume, area, hausdorff
# volume    1.55981668e-05 (true 1.55955788e-05): error +2.588e-09, tessellation -8.704e-15, bound 1.220e-16 -> wrong
# area      0.312071494 (true 0.312071466): error +2.796e-08, tessellation -1.555e-13 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_72():
    p0 = Box(center=(0.0, 0.0, 0.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.29237170472273677, 0.9563047559630354, -0.5), size=(0.5, 1.75, 0.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n2 = Union(p0, p1)
    p3 = Box(center=(0.25, 0.0, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Intersection(n2, p3)
    return tree


# case 73, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000100016594 (true 0.0001): error +1.659e-08, tessellation -1.388e-17, bound 1.331e-16 -> wrong
# area      2.00040007 (true 2.0004): error +6.638e-08, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from polygons) -> exact
# verdict   WRONG: volume, area, hausdorff
# case 73, pyvista: wrong volume, area, hausdorff, topology
# volume    0.000188896257 (true 0.0001): error +8.890e-05, tessellation -1.388e-17, bound 1.331e-16 -> wrong
# area      3.6888081 (true 2.0004): error +1.688e+00, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  17 components, genus 17, watertight False, winding consistent False (true: 1, genus 0, from polygons) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_73():
    p0 = Box(center=(0.25, 0.0, -0.75), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.29237170472273677, 0.9563047559630354, -0.5), size=(0.5, 1.75, 0.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n2 = Union(p0, p1)
    p3 = Box(center=(0.25, 0.0, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Intersection(n2, p3)
    return tree


# case 74, trimesh-manifold: wrong volume
# volume    0.878006359 (true 0.883672934): error -5.667e-03, tessellation -5.666e-03, bound 5.666e-03 -> wrong
# area      7.86443674 (true 7.89088623): error -2.645e-02, tessellation -2.645e-02 -> tessellation
# hausdorff mesh->true 3.606e-03, true->mesh 3.611e-03, tessellation 3.611e-03 -> tessellation
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: volume
# case 74, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.883672934): error -8.837e-01, tessellation -5.666e-03, bound 5.666e-03 -> wrong
# area      0 (true 7.89088623): error -7.891e+00, tessellation -2.645e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.611e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_74():
    p0 = Cylinder(center=(0.75, 0.5, -0.75), axis=(0.0, 0.0, 0.5), radius=0.75)
    p1 = Box(center=(-0.5, -0.25, 1.0), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 75, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0655498469): error -6.555e-02, tessellation -1.462e-03, bound 1.462e-03 -> wrong
# area      0 (true 2.78579816): error -2.786e+00, tessellation -9.569e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.234e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_75():
    p0 = Box(center=(0.75, 0.5, -0.75), size=(1.0, 1.0, 0.0001))
    p1 = Sphere(center=(0.5, 0.75, 0.0), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 76, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0655498469): error -6.555e-02, tessellation -1.462e-03, bound 1.462e-03 -> wrong
# area      0 (true 2.78579816): error -2.786e+00, tessellation -9.569e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.001e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_76():
    p0 = Box(center=(0.75, 0.75, -0.75), size=(1.0, 1.0, 0.0001))
    p1 = Sphere(center=(0.5, 0.75, 0.0), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 79, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0655498469): error -6.555e-02, tessellation -1.462e-03, bound 1.462e-03 -> wrong
# area      0 (true 2.78579816): error -2.786e+00, tessellation -9.569e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.994e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_79():
    p0 = Box(center=(0.5, 0.75, 0.0), size=(1.0, 1.0, 0.0001))
    p1 = Sphere(center=(0.0, 0.0, 0.0), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 86, trimesh-manifold: wrong topology
# volume    0.000780351253 (true 0.000785398163): error -5.047e-06, tessellation -5.037e-06, bound 1.050e-01 -> tessellation
# area      1.56389629 (true 1.57393792): error -1.004e-02, tessellation -1.008e-02 -> tessellation
# hausdorff mesh->true 9.647e-05, true->mesh 1.831e-04, tessellation 1.831e-04 -> tessellation
# topology  4 components, genus 1.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
def case_86():
    p0 = Cone(center=(-0.75, 0.75, 1.0), axis=(0.0, 1.5, 0.0), radius=1.25)
    p1 = Cylinder(center=(-0.25, -1.0, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Cylinder(center=(-0.25, -1.0, 0.25), axis=(0.375, -0.625, 1.25), radius=1.75)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Cylinder(center=(-0.25, -1.0, 0.25), axis=(0.0, 1.0, 0.0), radius=0.001)
    p6 = Cylinder(center=(-0.25, -1.0, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n7 = Union(p5, p6)
    tree = Intersection(n4, n7)
    return tree


# case 87, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_87():
    p0 = Cone(center=(-1.0, -0.75, 0.5), axis=(0.0, 2.0, 0.0), radius=2.0)
    p1 = Cone(center=(0.5, 0.0, -1.0), axis=(0.44999999999999996, -0.75, 1.5), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Box(center=(-0.75, 0.0, 0.75), size=(1.0, 1.0, 0.0001))
    p4 = Cylinder(center=(0.5, 0.0, 0.75), axis=(1.0, 1.0, 1.0), radius=0.001)
    n5 = Intersection(p3, p4)
    p6 = Ellipsoid(center=(0.0, -0.5, 1.0), radii=(0.75, 1.25, 1.5))
    n7 = Union(n5, p6)
    tree = Intersection(n2, n7)
    return tree


# case 88, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_88():
    p0 = Cone(center=(-1.0, -0.75, 0.5), axis=(0.0, 2.0, 0.0), radius=0.25)
    p1 = Cone(center=(0.5, 0.0, -1.0), axis=(0.44999999999999996, -0.75, 1.5), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Box(center=(-0.75, 0.0, 0.75), size=(1.0, 1.0, 0.0001))
    p4 = Cylinder(center=(0.5, 0.0, 0.75), axis=(1.0, 1.0, 1.0), radius=0.001)
    n5 = Intersection(p3, p4)
    p6 = Ellipsoid(center=(0.0, -0.5, 1.0), radii=(0.75, 1.25, 1.5))
    n7 = Union(n5, p6)
    tree = Intersection(n2, n7)
    return tree


# case 89, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_89():
    p0 = Cone(center=(-1.0, -0.75, 0.5), axis=(0.0, 2.0, 0.0), radius=0.25)
    p1 = Cone(center=(0.5, 0.0, -1.0), axis=(0.44999999999999996, -0.75, 1.5), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Box(center=(0.75, 0.0, 0.0), size=(1.0, 1.0, 0.0001))
    p4 = Cylinder(center=(0.5, 0.0, 0.75), axis=(1.0, 1.0, 1.0), radius=0.001)
    n5 = Intersection(p3, p4)
    p6 = Ellipsoid(center=(0.0, -0.5, 1.0), radii=(0.75, 1.25, 1.5))
    n7 = Union(n5, p6)
    tree = Intersection(n2, n7)
    return tree


# case 90, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_90():
    p0 = Cone(center=(-1.0, -0.75, 0.5), axis=(0.0, 2.0, 0.0), radius=0.25)
    p1 = Cone(center=(0.5, 0.0, -1.0), axis=(0.44999999999999996, -0.75, 1.5), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Box(center=(0.75, 0.0, 0.0), size=(1.0, 1.0, 0.0001))
    p4 = Cylinder(center=(0.5, 0.0, 0.75), axis=(1.0, 1.0, 1.0), radius=0.001)
    n5 = Intersection(p3, p4)
    p6 = Ellipsoid(center=(0.5, 0.0, 0.75), radii=(0.75, 1.25, 1.5))
    n7 = Union(n5, p6)
    tree = Intersection(n2, n7)
    return tree


# case 91, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_91():
    p0 = Cone(center=(0.5, 0.0, -1.0), axis=(0.44999999999999996, -0.75, 1.5), radius=0.5)
    p1 = Cone(center=(0.5, 0.0, -1.0), axis=(0.44999999999999996, -0.75, 1.5), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Box(center=(0.75, 0.0, 0.0), size=(1.0, 1.0, 0.0001))
    p4 = Cylinder(center=(0.5, 0.0, 0.75), axis=(1.0, 1.0, 1.0), radius=0.001)
    n5 = Intersection(p3, p4)
    p6 = Ellipsoid(center=(0.5, 0.0, 0.75), radii=(0.75, 1.25, 1.5))
    n7 = Union(n5, p6)
    tree = Intersection(n2, n7)
    return tree


# case 93, trimesh-manifold: wrong volume
# volume    9.3454446 (true 9.40588733): error -6.044e-02, tessellation -6.044e-02, bound 6.044e-02 -> wrong
# area      42.0456666 (true 42.2219797): error -1.763e-01, tessellation -1.763e-01 -> tessellation
# hausdorff mesh->true 9.589e-03, true->mesh 9.629e-03, tessellation 9.629e-03 -> tessellation
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: volume
def case_93():
    p0 = Box(center=(-1.0, -0.25, 0.25), size=(0.75, 0.5, 0.75))
    p1 = Cylinder(center=(-0.5, 0.25, 0.5), axis=(0.0, 0.0, 0.75), radius=2.0)
    n2 = Union(p0, p1)
    p3 = Box(center=(0.5915063509461096, -0.524519052838329, -0.75), size=(1.5, 1.0, 0.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    n4 = Union(n2, p3)
    p5 = Box(center=(0.3535533905932738, 0.35355339059327373, -0.5), size=(1.5, 1.25, 2.0), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 94, trimesh-manifold: wrong volume
# volume    8.75496019 (true 8.81540296): error -6.044e-02, tessellation -6.044e-02, bound 6.044e-02 -> wrong
# area      37.0687059 (true 37.2450192): error -1.763e-01, tessellation -1.763e-01 -> tessellation
# hausdorff mesh->true 9.631e-03, true->mesh 9.629e-03, tessellation 9.629e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> exact
# verdict   WRONG: volume
# case 94, pyvista: hung over 120 s
def case_94():
    p0 = Box(center=(-1.0, -0.25, 0.25), size=(0.75, 0.5, 0.75))
    p1 = Cylinder(center=(-0.5, 0.25, 0.5), axis=(0.0, 0.0, 0.75), radius=2.0)
    n2 = Union(p0, p1)
    p3 = Box(center=(-1.0, -0.25, 0.25), size=(0.75, 0.5, 0.75))
    n4 = Union(n2, p3)
    p5 = Box(center=(0.3535533905932738, 0.35355339059327373, -0.5), size=(1.5, 1.25, 2.0), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 95, trimesh-manifold: wrong volume
# volume    8.75496019 (true 8.81540296): error -6.044e-02, tessellation -6.044e-02, bound 6.044e-02 -> wrong
# area      37.0687059 (true 37.2450192): error -1.763e-01, tessellation -1.763e-01 -> tessellation
# hausdorff mesh->true 9.627e-03, true->mesh 9.619e-03, tessellation 9.630e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume
def case_95():
    p0 = Box(center=(-1.0, -0.25, 0.25), size=(0.75, 0.5, 0.75))
    p1 = Cylinder(center=(-0.5, 0.25, 0.5), axis=(0.0, 0.0, 0.75), radius=2.0)
    n2 = Union(p0, p1)
    p3 = Box(center=(-1.0, -0.25, 0.25), size=(0.25, 0.5, 0.75))
    n4 = Union(n2, p3)
    p5 = Box(center=(0.3535533905932738, 0.35355339059327373, -0.5), size=(1.5, 1.25, 2.0), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 96, pyvista: wrong volume, area, hausdorff, topology
# volume    1.58183448 (true 1.56165968): error +2.017e-02, tessellation -1.110e-02, bound 1.547e-02 -> wrong
# area      20.3688781 (true 20.1573438): error +2.115e-01, tessellation -8.426e-02 -> wrong
# hausdorff mesh->true 2.205e-01, true->mesh 2.043e-01, tessellation 6.759e-03 -> wrong
# topology  10 components, genus 10.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_96():
    p0 = Box(center=(-1.0, -0.25, 0.25), size=(0.75, 0.5, 0.75))
    p1 = Box(center=(-0.5580127018922193, -0.033493649053890295, 0.5), size=(0.25, 0.75, 2.0), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    n2 = Union(p0, p1)
    p3 = Sphere(center=(-0.25, 0.25, 0.25), radius=0.5)
    n4 = Union(n2, p3)
    p5 = Cone(center=(0.0, 0.25, 0.5), axis=(0.0, 0.0, 0.25), radius=1.5)
    tree = Union(n4, p5)
    return tree


# case 97, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.57833583): error -1.578e+00, tessellation -1.064e-02, bound 1.547e-02 -> wrong
# area      0 (true 20.3105503): error -2.031e+01, tessellation -8.261e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 5.922e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_97():
    p0 = Box(center=(-1.0, -0.25, 0.25), size=(0.75, 0.5, 0.75))
    p1 = Box(center=(-0.5580127018922193, -0.033493649053890295, 0.5), size=(0.25, 0.75, 2.0), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    n2 = Union(p0, p1)
    p3 = Sphere(center=(-0.25, 0.25, 0.25), radius=0.5)
    n4 = Union(n2, p3)
    p5 = Cone(center=(0.0, 0.5, 0.5), axis=(0.0, 0.0, 0.25), radius=1.5)
    tree = Union(n4, p5)
    return tree


# case 98, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.59433707): error -1.594e+00, tessellation -1.134e-02, bound 1.547e-02 -> wrong
# area      0 (true 21.0704942): error -2.107e+01, tessellation -8.734e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 5.922e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_98():
    p0 = Box(center=(-1.0, -0.25, -0.25), size=(0.75, 0.5, 0.75))
    p1 = Box(center=(-0.5580127018922193, -0.033493649053890295, 0.5), size=(0.25, 0.75, 2.0), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    n2 = Union(p0, p1)
    p3 = Sphere(center=(-0.25, 0.25, 0.25), radius=0.5)
    n4 = Union(n2, p3)
    p5 = Cone(center=(0.0, 0.5, 0.5), axis=(0.0, 0.0, 0.25), radius=1.5)
    tree = Union(n4, p5)
    return tree


# case 99, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.59280339): error -1.593e+00, tessellation -1.082e-02, bound 1.547e-02 -> wrong
# area      0 (true 21.0133028): error -2.101e+01, tessellation -8.734e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 5.922e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_99():
    p0 = Box(center=(-1.0, -0.25, -0.25), size=(0.75, 0.5, 0.75))
    p1 = Box(center=(-0.5580127018922193, -0.033493649053890295, 0.0), size=(0.25, 0.75, 2.0), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    n2 = Union(p0, p1)
    p3 = Sphere(center=(-0.25, 0.25, 0.25), radius=0.5)
    n4 = Union(n2, p3)
    p5 = Cone(center=(0.0, 0.5, 0.5), axis=(0.0, 0.0, 0.25), radius=1.5)
    tree = Union(n4, p5)
    return tree


# case 105, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_105():
    p0 = Cone(center=(-0.5, 0.5, -0.5), axis=(0.75, 0.75, 0.75), radius=0.25)
    p1 = Box(center=(0.25, 0.0, 0.0), size=(1.0, 1.0, 0.0001))
    p2 = Cylinder(center=(0.0, 0.75, 0.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    n3 = Difference(p1, p2)
    p4 = Box(center=(0.25, 0.0, 0.0), size=(1.0, 1.0, 0.0001))
    n5 = Difference(n3, p4)
    n6 = Difference(p0, n5)
    p7 = Box(center=(0.25, 0.0, 0.0), size=(1.0, 1.0, 0.0001))
    tree = Intersection(n6, p7)
    return tree


# case 111, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.321858792): error -3.219e-01, tessellation -2.226e-02, bound 1.169e+00 -> tessellation
# area      0 (true 4.44244922): error -4.442e+00, tessellation -1.552e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.918e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_111():
    p0 = Torus(center=(-0.5, -0.5, -0.5), axis=(1.0, 0.0, 0.0), major=2.0, minor=1.0)
    p1 = Cylinder(center=(-0.5, 0.0, -0.75), axis=(0.075, -0.125, 0.25), radius=1.5)
    n2 = Union(p0, p1)
    p3 = Sphere(center=(0.0, -1.0, -0.75), radius=0.75)
    tree = Intersection(n2, p3)
    return tree


# case 112, pyvista: wrong topology
# volume    0.385823687 (true 0.409629436): error -2.381e-02, tessellation -2.370e-02, bound 1.169e+00 -> tessellation
# area      5.09077422 (true 5.29477669): error -2.040e-01, tessellation -2.061e-01 -> tessellation
# hausdorff mesh->true 1.867e-02, true->mesh 1.858e-02, tessellation 1.872e-02 -> tessellation
# topology  3 components, genus 1, watertight False, winding consistent False (true: 2, genus 0) -> wrong
# verdict   WRONG: topology
def case_112():
    p0 = Torus(center=(-0.5, -0.5, -0.5), axis=(1.0, 0.0, 0.0), major=2.0, minor=1.0)
    p1 = Cylinder(center=(-0.5, 0.0, 0.0), axis=(0.075, -0.125, 0.25), radius=1.5)
    n2 = Union(p0, p1)
    p3 = Sphere(center=(0.0, -1.0, -0.75), radius=0.75)
    tree = Intersection(n2, p3)
    return tree


# case 113, pyvista: wrong topology
# volume    0.0380028996 (true 0.0389609979): error -9.581e-04, tessellation -1.099e-03, bound 1.131e+00 -> tessellation
# area      0.623395698 (true 0.625026176): error -1.630e-03, tessellation -1.096e-02 -> tessellation
# hausdorff mesh->true 7.195e-03, true->mesh 7.210e-03, tessellation 7.221e-03 -> tessellation
# topology  4 components, genus 2.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_113():
    p0 = Torus(center=(-0.5, -0.5, -0.5), axis=(1.0, 0.0, 0.0), major=2.0, minor=1.0)
    p1 = Cylinder(center=(-0.5, 0.0, 0.0), axis=(0.075, -0.125, 0.25), radius=1.5)
    n2 = Union(p0, p1)
    p3 = Sphere(center=(0.0, -1.0, -0.75), radius=0.25)
    tree = Intersection(n2, p3)
    return tree


# case 114, pyvista: wrong area, hausdorff, topology
# volume    0.0353753241 (true 0.0355982399): error -2.229e-04, tessellation -6.840e-04, bound 1.131e+00 -> tessellation
# area      0.645265078 (true 0.612479908): error +3.279e-02, tessellation -8.212e-03 -> wrong
# hausdorff mesh->true 3.308e-01, true->mesh 3.025e-03, tessellation 3.025e-03 -> wrong
# topology  4 components, genus 2.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_114():
    p0 = Torus(center=(-0.5, -0.5, -0.5), axis=(1.0, 0.0, 0.0), major=2.0, minor=1.0)
    p1 = Cylinder(center=(-0.5, 0.0, 0.0), axis=(0.075, -0.125, 0.25), radius=1.5)
    n2 = Union(p0, p1)
    p3 = Sphere(center=(0.0, -1.0, -0.5), radius=0.25)
    tree = Intersection(n2, p3)
    return tree


# case 115, pyvista: wrong topology
# volume    39.9470489 (true 41.03628): error -1.089e+00, tessellation -1.116e+00, bound 1.131e+00 -> tessellation
# area      90.3980906 (true 90.8979518): error -4.999e-01, tessellation -6.335e-01 -> tessellation
# hausdorff mesh->true 2.495e-02, true->mesh 2.497e-02, tessellation 2.530e-02 -> tessellation
# topology  1 components, genus 1.5, watertight False, winding consistent False (true: 1, genus 1) -> wrong
# verdict   WRONG: topology
def case_115():
    p0 = Torus(center=(-0.5, -0.5, -0.5), axis=(1.0, 0.0, 0.0), major=2.0, minor=1.0)
    p1 = Cylinder(center=(-0.5, 0.0, 0.0), axis=(0.075, -0.125, 0.25), radius=1.5)
    n2 = Union(p0, p1)
    p3 = Sphere(center=(0.0, -1.0, -0.5), radius=0.25)
    tree = Union(n2, p3)
    return tree


# case 116, pyvista: wrong hausdorff, topology
# volume    40.0172182 (true 41.1360109): error -1.119e+00, tessellation -1.111e+00, bound 1.131e+00 -> tessellation
# area      90.6126476 (true 90.9398034): error -3.272e-01, tessellation -5.855e-01 -> tessellation
# hausdorff mesh->true 4.073e-02, true->mesh 2.376e-02, tessellation 2.543e-02 -> wrong
# topology  2 components, genus 5, watertight False, winding consistent False (true: 1, genus 2) -> wrong
# verdict   WRONG: hausdorff, topology
def case_116():
    p0 = Torus(center=(-0.5, -0.5, -0.5), axis=(1.0, 0.0, 0.0), major=2.0, minor=1.0)
    p1 = Cylinder(center=(-0.5, -0.5, 0.0), axis=(0.075, -0.125, 0.25), radius=1.5)
    n2 = Union(p0, p1)
    p3 = Sphere(center=(0.0, -1.0, -0.5), radius=0.25)
    tree = Union(n2, p3)
    return tree


# case 117, trimesh-manifold: wrong hausdorff
# volume    0.282910806 (true 0.282920796): error -9.991e-06, tessellation -1.007e-05, bound 1.007e-05 -> tessellation
# area      7.75311867 (true 7.77327584): error -2.016e-02, tessellation -2.016e-02 -> tessellation
# hausdorff mesh->true 5.542e-08, true->mesh 4.911e-08, tessellation 1.665e-16 -> wrong
# topology  4 components, genus 0, watertight True, winding consistent True (true: 4, genus 0) -> exact
# verdict   WRONG: hausdorff
def case_117():
    p0 = Box(center=(-0.06698729810778059, 1.1160254037844386, -0.75), size=(0.75, 0.5, 0.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Cylinder(center=(0.25, -0.25, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(0.25, -1.0, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p4 = Box(center=(0.5, 0.0, -0.25), size=(1.0, 1.0, 0.0001))
    n5 = Union(p3, p4)
    tree = Union(n2, n5)
    return tree


# case 126, pyvista: crashed (exit code -11)
def case_126():
    p0 = Sphere(center=(0.5, -1.0, -0.25), radius=0.5)
    p1 = Cylinder(center=(-0.75, -0.75, -1.0), axis=(1.75, 1.75, 1.75), radius=1.5)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-0.75, -0.75, -1.0), axis=(1.75, 1.75, 1.75), radius=1.5)
    tree = Union(n2, p3)
    return tree


# case 127, trimesh-manifold: wrong topology
# volume    21.2996187 (true 21.4362716): error -1.367e-01, tessellation -1.367e-01, bound 1.687e-01 -> tessellation
# area      42.5970439 (true 42.7307708): error -1.337e-01, tessellation -1.337e-01 -> tessellation
# hausdorff mesh->true 7.223e-03, true->mesh 7.223e-03, tessellation 7.223e-03 -> tessellation
# topology  5 components, genus 2, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
# case 127, pyvista: hung over 120 s
def case_127():
    p0 = Sphere(center=(0.5, -1.0, -0.25), radius=0.5)
    p1 = Cylinder(center=(-0.75, -0.75, -1.0), axis=(1.75, 1.75, 1.75), radius=1.5)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-0.75, -0.75, -1.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    tree = Union(n2, p3)
    return tree


# case 128, trimesh-manifold: wrong topology
# volume    21.3141021 (true 21.4518516): error -1.377e-01, tessellation -1.377e-01, bound 1.687e-01 -> tessellation
# area      42.6266654 (true 42.7629244): error -1.363e-01, tessellation -1.363e-01 -> tessellation
# hausdorff mesh->true 7.223e-03, true->mesh 7.223e-03, tessellation 7.223e-03 -> tessellation
# topology  5 components, genus 2, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
# case 128, pyvista: hung over 120 s
def case_128():
    p0 = Sphere(center=(0.5, -0.75, -0.25), radius=0.5)
    p1 = Cylinder(center=(-0.75, -0.75, -1.0), axis=(1.75, 1.75, 1.75), radius=1.5)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-0.75, -0.75, -1.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    tree = Union(n2, p3)
    return tree


# case 131, pyvista: wrong topology
# volume    6.46393499 (true 6.49817891): error -3.424e-02, tessellation -7.093e-02, bound 3.772e-01 -> tessellation
# area      23.4211274 (true 23.3692145): error +5.191e-02, tessellation -1.701e-01 -> tessellation
# hausdorff mesh->true 1.798e-02, true->mesh 1.806e-02, tessellation 1.806e-02 -> tessellation
# topology  1 components, genus 1.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_131():
    p0 = Truncus(center=(-0.5, -0.75, -0.25), axis=(2.0, 2.0, 2.0), r1=1.0, r2=0.25)
    p1 = Sphere(center=(0.0, 0.0, 0.0), radius=1.5)
    p2 = Cone(center=(0.75, 0.25, 0.75), axis=(0.0, 1.5, 0.0), radius=1.75)
    n3 = Intersection(p1, p2)
    p4 = Cylinder(center=(-0.75, -1.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Union(n3, p4)
    tree = Union(p0, n5)
    return tree


# case 132, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_132():
    p0 = Truncus(center=(-0.5, -0.75, -0.25), axis=(2.0, 2.0, 2.0), r1=1.0, r2=0.25)
    p1 = Sphere(center=(0.0, 0.0, 0.0), radius=0.25)
    p2 = Cone(center=(0.75, 0.25, 0.75), axis=(0.0, 1.5, 0.0), radius=1.75)
    n3 = Intersection(p1, p2)
    p4 = Cylinder(center=(-0.75, -1.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Union(n3, p4)
    tree = Union(p0, n5)
    return tree


# case 133, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_133():
    p0 = Truncus(center=(-0.5, -0.75, 0.25), axis=(2.0, 2.0, 2.0), r1=1.0, r2=0.25)
    p1 = Sphere(center=(0.0, 0.0, 0.0), radius=0.25)
    p2 = Cone(center=(0.75, 0.25, 0.75), axis=(0.0, 1.5, 0.0), radius=1.75)
    n3 = Intersection(p1, p2)
    p4 = Cylinder(center=(-0.75, -1.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Union(n3, p4)
    tree = Union(p0, n5)
    return tree


# case 134, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_134():
    p0 = Truncus(center=(-0.5, -0.75, 0.25), axis=(0.0, 2.0, 0.0), r1=1.0, r2=0.25)
    p1 = Sphere(center=(0.0, 0.0, 0.0), radius=0.25)
    p2 = Cone(center=(0.75, 0.25, 0.75), axis=(0.0, 1.5, 0.0), radius=1.75)
    n3 = Intersection(p1, p2)
    p4 = Cylinder(center=(-0.75, -1.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Union(n3, p4)
    tree = Union(p0, n5)
    return tree


# case 135, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_135():
    p0 = Truncus(center=(-0.5, -0.75, 0.25), axis=(0.0, 2.0, 0.0), r1=1.0, r2=0.25)
    p1 = Sphere(center=(0.0, 0.0, 0.0), radius=0.25)
    p2 = Cone(center=(0.75, 0.25, 0.75), axis=(0.0, 1.5, 0.0), radius=1.75)
    n3 = Intersection(p1, p2)
    p4 = Cylinder(center=(-0.75, -1.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Intersection(n3, p4)
    tree = Union(p0, n5)
    return tree


# case 137, trimesh-manifold: wrong hausdorff
# volume    0 (true 0): error +0.000e+00, tessellation +0.000e+00, bound 6.716e-03 -> exact
# area      0.836603107 (true 0): error +8.366e-01, tessellation +8.366e-01 -> tessellation
# hausdorff mesh->true 5.617e-08, true->mesh 0.000e+00, tessellation 1.110e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: hausdorff
# case 137, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0): error +0.000e+00, tessellation +0.000e+00, bound 6.716e-03 -> exact
# area      8.22722208 (true 0): error +8.227e+00, tessellation +8.366e-01 -> wrong
# hausdorff mesh->true 1.654e+00, true->mesh 0.000e+00, tessellation 1.110e-16 -> wrong
# topology  5 components, genus 6, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_137():
    p0 = Box(center=(0.2745190528383291, 1.024519052838329, -0.75), size=(1.0, 2.0, 0.25), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Cone(center=(0.25, 0.75, -1.0), axis=(0.0, 0.0, 0.25), radius=2.0)
    tree = Intersection(p0, p1)
    return tree


# case 138, trimesh-manifold: wrong area, hausdorff
# volume    0.500000001 (true 0.5): error +1.431e-09, tessellation -1.665e-16, bound 1.110e-16 -> exact
# area      5.50000001 (true 5.5): error +9.067e-09, tessellation -1.776e-15 -> wrong
# hausdorff mesh->true 5.617e-08, true->mesh 4.125e-08, tessellation 2.483e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: area, hausdorff
def case_138():
    p0 = Box(center=(0.2745190528383291, 1.024519052838329, -0.75), size=(1.0, 2.0, 0.25), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.2745190528383291, 1.024519052838329, -0.75), size=(1.0, 2.0, 0.25), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Intersection(p0, p1)
    return tree


# case 139, trimesh-manifold: wrong area, hausdorff
# volume    0.500000001 (true 0.5): error +1.431e-09, tessellation -1.665e-16, bound 4.996e-16 -> exact
# area      5.50000001 (true 5.5): error +9.067e-09, tessellation -1.776e-15 -> wrong
# hausdorff mesh->true 5.617e-08, true->mesh 4.136e-08, tessellation 3.331e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: area, hausdorff
# case 139, pyvista: wrong volume, area, hausdorff, topology
# volume    2.31759543 (true 0.5): error +1.818e+00, tessellation -1.665e-16, bound 4.996e-16 -> wrong
# area      10.7187499 (true 5.5): error +5.219e+00, tessellation -1.776e-15 -> wrong
# hausdorff mesh->true 8.750e-01, true->mesh 4.136e-08, tessellation 3.331e-16 -> wrong
# topology  11 components, genus 12.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_139():
    p0 = Box(center=(0.2745190528383291, 1.024519052838329, -0.75), size=(1.0, 2.0, 0.25), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.2745190528383291, 1.024519052838329, -0.75), size=(1.0, 2.0, 2.0), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Intersection(p0, p1)
    return tree


# case 140, trimesh-manifold: wrong hausdorff
# volume    2.00000001 (true 2): error +5.724e-09, tessellation -6.661e-16, bound 6.661e-16 -> exact
# area      10 (true 10): error +1.925e-09, tessellation +0.000e+00 -> exact
# hausdorff mesh->true 5.617e-08, true->mesh 4.206e-08, tessellation 4.696e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: hausdorff
# case 140, pyvista: wrong volume, area, hausdorff, topology
# volume    4.4493055 (true 2): error +2.449e+00, tessellation -6.661e-16, bound 6.661e-16 -> wrong
# area      17.5624999 (true 10): error +7.562e+00, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 5.000e-01, true->mesh 4.206e-08, tessellation 4.696e-16 -> wrong
# topology  10 components, genus 11, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_140():
    p0 = Box(center=(0.2745190528383291, 1.024519052838329, -0.75), size=(1.0, 2.0, 1.0), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.2745190528383291, 1.024519052838329, -0.75), size=(1.0, 2.0, 2.0), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Intersection(p0, p1)
    return tree


# case 141, trimesh-manifold: wrong volume, area, hausdorff
# volume    4.00000001 (true 4): error +1.145e-08, tessellation -4.441e-16, bound 8.882e-16 -> wrong
# area      16 (true 16): error -7.598e-09, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 5.617e-08, true->mesh 4.164e-08, tessellation 4.674e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_141():
    p0 = Box(center=(0.2745190528383291, 1.024519052838329, -0.75), size=(1.0, 2.0, 2.0), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.2745190528383291, 1.024519052838329, -0.75), size=(1.0, 2.0, 2.0), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Intersection(p0, p1)
    return tree


# case 144, trimesh-manifold: wrong hausdorff
# volume    0.0235501766 (true 0.0235580663): error -7.890e-06, tessellation -7.885e-06, bound 1.058e-01 -> exact
# area      0.861904501 (true 0.861976558): error -7.206e-05, tessellation -7.199e-05 -> exact
# hausdorff mesh->true 2.501e-08, true->mesh 2.448e-08, tessellation 1.110e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: hausdorff
def case_144():
    p0 = Box(center=(0.8832118297823512, 0.5314478937134957, 0.75), size=(0.25, 1.0, 0.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Truncus(center=(0.0, 1.0, -0.75), axis=(1.5, 0.0, 0.0), r1=2.0, r2=0.5)
    p2 = Box(center=(-8.326672684688674e-17, -1.0606601717798214, -0.25), size=(1.5, 0.5, 0.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n3 = Intersection(p1, p2)
    p4 = Truncus(center=(0.0, 1.0, -0.75), axis=(1.5, 0.0, 0.0), r1=2.0, r2=0.5)
    n5 = Union(n3, p4)
    tree = Intersection(p0, n5)
    return tree


# case 145, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_145():
    p0 = Box(center=(0.8832118297823512, 0.5314478937134957, 0.75), size=(0.25, 1.0, 0.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Truncus(center=(0.0, 1.0, -0.75), axis=(1.5, 0.0, 0.0), r1=2.0, r2=0.5)
    p2 = Box(center=(-0.49794978843022397, -0.9365073455143291, -0.25), size=(1.5, 0.5, 0.5), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n3 = Intersection(p1, p2)
    p4 = Truncus(center=(0.0, 1.0, -0.75), axis=(1.5, 0.0, 0.0), r1=2.0, r2=0.5)
    n5 = Union(n3, p4)
    tree = Intersection(p0, n5)
    return tree


# case 146, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_146():
    p0 = Box(center=(0.8832118297823512, 0.5314478937134957, 0.75), size=(0.25, 1.0, 0.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Truncus(center=(0.0, 1.0, -0.75), axis=(1.5, 0.0, 0.0), r1=2.0, r2=0.25)
    p2 = Box(center=(-0.49794978843022397, -0.9365073455143291, -0.25), size=(1.5, 0.5, 0.5), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n3 = Intersection(p1, p2)
    p4 = Truncus(center=(0.0, 1.0, -0.75), axis=(1.5, 0.0, 0.0), r1=2.0, r2=0.5)
    n5 = Union(n3, p4)
    tree = Intersection(p0, n5)
    return tree


# case 148, trimesh-manifold: wrong hausdorff
# volume    0.0235501766 (true 0.0235579921): error -7.816e-06, tessellation -7.811e-06, bound 9.885e-02 -> exact
# area      0.861904501 (true 0.861976549): error -7.205e-05, tessellation -7.198e-05 -> exact
# hausdorff mesh->true 2.460e-08, true->mesh 2.415e-08, tessellation 1.110e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: hausdorff
# case 148, pyvista: wrong volume, area, hausdorff, topology
# volume    -0.222973576 (true 0.0235579921): error -2.465e-01, tessellation -7.811e-06, bound 9.885e-02 -> wrong
# area      0.533206262 (true 0.861976549): error -3.288e-01, tessellation -7.198e-05 -> wrong
# hausdorff mesh->true 2.467e-08, true->mesh 1.039e-01, tessellation 1.110e-16 -> wrong
# topology  2 components, genus 1, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_148():
    p0 = Box(center=(0.8832118297823512, 0.5314478937134957, 0.75), size=(0.25, 1.0, 0.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Truncus(center=(0.0, 1.0, -0.75), axis=(1.5, 0.0, 0.0), r1=2.0, r2=0.25)
    p2 = Box(center=(0.8832118297823512, 0.5314478937134957, 0.75), size=(0.25, 1.0, 0.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n3 = Intersection(p1, p2)
    p4 = Truncus(center=(0.0, 1.0, -0.75), axis=(1.5, 0.0, 0.0), r1=2.0, r2=0.5)
    n5 = Union(n3, p4)
    tree = Intersection(p0, n5)
    return tree


# case 149, pyvista: wrong area, hausdorff, topology
# volume    0 (true 3.14159265e-06): error -3.142e-06, tessellation -2.015e-08, bound 1.786e-02 -> tessellation
# area      0 (true 0.00628946849): error -6.289e-03, tessellation -1.013e-05 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 4.815e-06 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_149():
    p0 = Cylinder(center=(-1.0, 0.75, -1.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    p1 = Cylinder(center=(-0.25, -0.25, 0.0), axis=(0.075, -0.125, 0.25), radius=1.75)
    tree = Difference(p0, p1)
    return tree


# case 151, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0981747704): error -9.817e-02, tessellation -6.296e-04, bound 2.092e-03 -> wrong
# area      0 (true 1.17809725): error -1.178e+00, tessellation -3.779e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.204e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_151():
    p0 = Cylinder(center=(-1.0, 0.75, -1.0), axis=(0.0, 0.5, 0.0), radius=0.25)
    p1 = Sphere(center=(0.0, 1.0, 0.25), radius=0.25)
    tree = Difference(p0, p1)
    return tree


# case 152, pyvista: crashed (exit code -11)
def case_152():
    p0 = Cylinder(center=(0.0, 1.0, 0.25), axis=(0.0, 0.5, 0.0), radius=0.25)
    p1 = Sphere(center=(0.0, 1.0, 0.25), radius=0.25)
    tree = Difference(p0, p1)
    return tree


# case 154, pyvista: wrong area, topology
# volume    0.00411510414 (true 0.00310062421): error +1.014e-03, tessellation +1.218e-03, bound 9.420e-02 -> tessellation
# area      0.468281265 (true 0.445737841): error +2.254e-02, tessellation +7.651e-03 -> wrong
# hausdorff mesh->true 1.003e-02, true->mesh 9.510e-03, tessellation 9.615e-03 -> tessellation
# topology  1 components, genus 1, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: area, topology
def case_154():
    p0 = Cylinder(center=(0.0, 1.0, 0.25), axis=(0.0, 0.5, 0.0), radius=0.25)
    p1 = Sphere(center=(0.0, 0.25, 0.25), radius=1.0)
    tree = Difference(p0, p1)
    return tree


# case 158, trimesh-manifold: wrong area, hausdorff
# volume    9.99569893e-05 (true 0.000100000017): error -4.303e-08, tessellation -1.652e-11, bound 4.664e-08 -> tessellation
# area      2.00039983 (true 2.0004): error -1.721e-07, tessellation -8.561e-11 -> wrong
# hausdorff mesh->true 5.131e-08, true->mesh 5.131e-08, tessellation 1.055e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> exact
# verdict   WRONG: area, hausdorff
def case_158():
    p0 = Cylinder(center=(-1.0, 0.0, -0.75), axis=(0.3, -0.5, 1.0), radius=0.001)
    p1 = Box(center=(-0.75, -0.75, -1.0), size=(1.0, 1.0, 0.0001))
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-1.0, 0.0, -0.75), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Difference(n2, p3)
    return tree


# case 163, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_163():
    p0 = Sphere(center=(0.75, -1.0, -0.25), radius=1.25)
    p1 = Sphere(center=(0.75, -1.0, -0.25), radius=1.25)
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.0, 0.5, 0.5), size=(1.75, 1.0, 1.0))
    p4 = Sphere(center=(-0.5, 0.5, 0.75), radius=0.75)
    n5 = Union(p3, p4)
    n6 = Difference(n2, n5)
    p7 = Truncus(center=(-0.5, 0.75, 0.0), axis=(0.0, 1.75, 0.0), r1=2.0, r2=1.25)
    tree = Union(n6, p7)
    return tree


# case 164, trimesh-manifold: wrong topology
# volume    0 (true 0): error +0.000e+00, tessellation +2.891e-19, bound 4.997e-01 -> exact
# area      0 (true 0): error +0.000e+00, tessellation +3.002e-02 -> exact
# hausdorff mesh->true 0.000e+00, true->mesh 0.000e+00, tessellation 1.198e-02 -> exact
# topology  0 components, genus 0, watertight True, winding consistent True (true: 5, genus 0) -> wrong
# verdict   WRONG: topology
def case_164():
    p0 = Sphere(center=(0.75, -1.0, -0.25), radius=1.25)
    p1 = Sphere(center=(0.75, -1.0, -0.25), radius=1.25)
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.0, 0.5, 0.5), size=(1.75, 1.0, 1.0))
    p4 = Sphere(center=(-0.5, 0.5, 0.75), radius=0.75)
    n5 = Union(p3, p4)
    n6 = Difference(n2, n5)
    p7 = Truncus(center=(-0.5, 0.75, 0.0), axis=(0.0, 1.75, 0.0), r1=2.0, r2=1.25)
    tree = Difference(n6, p7)
    return tree


# case 170, trimesh-manifold: wrong area
# volume    0.0759642336 (true 0.0778731351): error -1.909e-03, tessellation -1.958e-03, bound 2.120e-01 -> tessellation
# area      3.12636882 (true 2.81105117): error +3.153e-01, tessellation +1.475e-01 -> wrong
# hausdorff mesh->true 1.476e-02, true->mesh 1.477e-02, tessellation 1.560e-02 -> tessellation
# topology  3 components, genus 3, watertight False, winding consistent False (true: 3, genus 2) -> not comparable
# verdict   WRONG: area
def case_170():
    p0 = Ellipsoid(center=(-1.0, 0.25, 0.25), radii=(1.25, 0.5, 0.25))
    p1 = Sphere(center=(-0.75, 0.75, -0.25), radius=1.25)
    p2 = Box(center=(1.3660254037844386, -0.36602540378443876, -0.75), size=(1.25, 1.0, 0.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p3 = Ellipsoid(center=(-1.0, 0.25, 0.25), radii=(1.25, 0.5, 0.25))
    n4 = Union(p2, p3)
    n5 = Intersection(p1, n4)
    n6 = Difference(p0, n5)
    p7 = Cylinder(center=(0.0, 0.75, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Union(n6, p7)
    return tree


# case 174, pyvista: hung over 120 s
def case_174():
    p0 = Cone(center=(0.25, 0.25, 0.5), axis=(0.3, -0.5, 1.0), radius=0.25)
    p1 = Box(center=(0.5, 0.0, 0.75), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.5, -0.75, 0.5), axis=(1.0, 1.0, 1.0), radius=0.75)
    tree = Union(n2, p3)
    return tree


# case 175, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 3.06079198): error -3.061e+00, tessellation -1.963e-02, bound 2.012e-02 -> wrong
# area      0 (true 11.8063177): error -1.181e+01, tessellation -3.461e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.611e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_175():
    p0 = Cone(center=(0.25, 0.25, 0.5), axis=(0.3, -0.5, 1.0), radius=0.25)
    p1 = Box(center=(0.5, 0.5, 0.75), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.5, -0.75, 0.5), axis=(1.0, 1.0, 1.0), radius=0.75)
    tree = Union(n2, p3)
    return tree


# case 176, pyvista: wrong area, hausdorff, topology
# volume    0 (true 4.88052899e-06): error -4.881e-06, tessellation -1.256e-07, bound 2.012e-02 -> exact
# area      0 (true 0.0973601296): error -9.736e-02, tessellation -2.163e-03 -> wrong
# hausdorff mesh->true 0.000e+00, true->mesh inf, tessellation 3.537e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_176():
    p0 = Cone(center=(0.25, 0.25, 0.5), axis=(0.3, -0.5, 1.0), radius=0.25)
    p1 = Box(center=(0.5, 0.5, 0.75), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.5, -0.75, 0.5), axis=(1.0, 1.0, 1.0), radius=0.75)
    tree = Intersection(n2, p3)
    return tree


# case 179, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 9.81747704): error -9.817e+00, tessellation -6.296e-02, bound 6.296e-02 -> wrong
# area      0 (true 35.3429174): error -3.534e+01, tessellation -1.511e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 6.019e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_179():
    p0 = Cylinder(center=(0.0, -0.75, -0.75), axis=(0.0, 0.0, 1.0), radius=1.25)
    p1 = Cylinder(center=(0.5, 0.75, 0.75), axis=(0.0, 0.0, 1.0), radius=1.25)
    tree = Union(p0, p1)
    return tree


# case 180, pyvista: wrong hausdorff, topology
# volume    9.45931551 (true 9.50789985): error -4.858e-02, tessellation -5.847e-02, bound 6.296e-02 -> tessellation
# area      31.7451777 (true 31.7577079): error -1.253e-02, tessellation -1.101e-01 -> exact
# hausdorff mesh->true 3.272e-02, true->mesh 6.019e-03, tessellation 6.019e-03 -> wrong
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: hausdorff, topology
def case_180():
    p0 = Cylinder(center=(0.0, -0.75, 0.0), axis=(0.0, 0.0, 1.0), radius=1.25)
    p1 = Cylinder(center=(0.5, 0.75, 0.75), axis=(0.0, 0.0, 1.0), radius=1.25)
    tree = Union(p0, p1)
    return tree


# case 182, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_182():
    p0 = Truncus(center=(0.25, -0.5, 0.25), axis=(1.5, 0.0, 0.0), r1=0.5, r2=0.75)
    p1 = Cone(center=(0.75, 1.0, 0.5), axis=(1.0, 1.0, 1.0), radius=0.75)
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(-0.75, 0.5, -0.25), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.5, minor=0.1)
    p4 = Ellipsoid(center=(0.25, 0.0, 0.25), radii=(0.5, 1.5, 0.25))
    n5 = Difference(p3, p4)
    tree = Difference(n2, n5)
    return tree


# case 190, manifold3d: wrong hausdorff
# volume    0.00108036129 (true 0.00108539816): error -5.037e-06, tessellation -5.037e-06, bound 8.777e-03 -> tessellation
# area      7.56505912 (true 7.57513792): error -1.008e-02, tessellation -1.008e-02 -> tessellation
# hausdorff mesh->true 4.799e-04, true->mesh 5.551e-17, tessellation 1.110e-16 -> wrong
# topology  4 components, genus 0, watertight True, winding consistent True (true: 4, genus 0) -> exact
# verdict   WRONG: hausdorff
# case 190, trimesh-manifold: wrong hausdorff
# volume    0.00108033318 (true 0.00108539816): error -5.065e-06, tessellation -5.037e-06, bound 8.777e-03 -> tessellation
# area      7.56505901 (true 7.57513792): error -1.008e-02, tessellation -1.008e-02 -> tessellation
# hausdorff mesh->true 5.204e-08, true->mesh 5.131e-08, tessellation 1.110e-16 -> wrong
# topology  4 components, genus 0, watertight True, winding consistent True (true: 4, genus 0) -> exact
# verdict   WRONG: hausdorff
def case_190():
    p0 = Box(center=(0.25, -0.25, -1.0), size=(1.0, 1.0, 0.0001))
    p1 = Cylinder(center=(0.25, -0.75, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n2 = Union(p0, p1)
    p3 = Box(center=(0.5, -0.25, -0.25), size=(1.0, 1.0, 0.0001))
    p4 = Box(center=(1.0, 1.0, 0.0), size=(1.0, 1.0, 0.0001))
    n5 = Union(p3, p4)
    n6 = Union(n2, n5)
    p7 = Ellipsoid(center=(1.0, 0.0, 0.75), radii=(1.5, 0.25, 0.25))
    tree = Difference(n6, p7)
    return tree


# case 196, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_196():
    p0 = Cylinder(center=(0.25, -0.25, -0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    p1 = Cone(center=(-0.5, -0.25, -1.0), axis=(1.0, 0.0, 0.0), radius=1.75)
    p2 = Box(center=(-0.649519052838329, -0.37499999999999994, -0.75), size=(0.75, 0.75, 1.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p3 = Cylinder(center=(-0.25, 0.75, -0.75), axis=(0.0, 1.0, 0.0), radius=0.001)
    n4 = Intersection(p2, p3)
    p5 = Cone(center=(0.5, -1.0, -0.25), axis=(2.0, 2.0, 2.0), radius=0.75)
    n6 = Intersection(n4, p5)
    n7 = Union(p1, n6)
    tree = Union(p0, n7)
    return tree


# case 197, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_197():
    p0 = Cylinder(center=(0.25, -0.25, -0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    p1 = Cone(center=(0.5, -1.0, -0.25), axis=(2.0, 2.0, 2.0), radius=0.75)
    p2 = Box(center=(-0.649519052838329, -0.37499999999999994, -0.75), size=(0.75, 0.75, 1.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p3 = Cylinder(center=(-0.25, 0.75, -0.75), axis=(0.0, 1.0, 0.0), radius=0.001)
    n4 = Intersection(p2, p3)
    p5 = Cone(center=(0.5, -1.0, -0.25), axis=(2.0, 2.0, 2.0), radius=0.75)
    n6 = Intersection(n4, p5)
    n7 = Union(p1, n6)
    tree = Union(p0, n7)
    return tree


# case 198, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_198():
    p0 = Cylinder(center=(0.25, -0.25, -0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    p1 = Cone(center=(0.5, -1.0, -0.25), axis=(2.0, 2.0, 2.0), radius=0.75)
    p2 = Box(center=(-0.649519052838329, -0.37499999999999994, -0.75), size=(0.75, 0.75, 1.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p3 = Cylinder(center=(-0.25, 0.75, -0.75), axis=(0.0, 1.0, 0.0), radius=0.001)
    n4 = Intersection(p2, p3)
    p5 = Cone(center=(0.5, -1.0, 0.25), axis=(2.0, 2.0, 2.0), radius=0.75)
    n6 = Intersection(n4, p5)
    n7 = Union(p1, n6)
    tree = Union(p0, n7)
    return tree


# case 199, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_199():
    p0 = Cylinder(center=(0.25, -0.25, -0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    p1 = Cone(center=(0.5, -1.0, 0.0), axis=(2.0, 2.0, 2.0), radius=0.75)
    p2 = Box(center=(-0.649519052838329, -0.37499999999999994, -0.75), size=(0.75, 0.75, 1.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p3 = Cylinder(center=(-0.25, 0.75, -0.75), axis=(0.0, 1.0, 0.0), radius=0.001)
    n4 = Intersection(p2, p3)
    p5 = Cone(center=(0.5, -1.0, 0.25), axis=(2.0, 2.0, 2.0), radius=0.75)
    n6 = Intersection(n4, p5)
    n7 = Union(p1, n6)
    tree = Union(p0, n7)
    return tree


# case 200, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_200():
    p0 = Cylinder(center=(-0.25, 0.75, -0.75), axis=(0.0, 1.0, 0.0), radius=0.001)
    p1 = Cone(center=(0.5, -1.0, 0.0), axis=(2.0, 2.0, 2.0), radius=0.75)
    p2 = Box(center=(-0.649519052838329, -0.37499999999999994, -0.75), size=(0.75, 0.75, 1.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p3 = Cylinder(center=(-0.25, 0.75, -0.75), axis=(0.0, 1.0, 0.0), radius=0.001)
    n4 = Intersection(p2, p3)
    p5 = Cone(center=(0.5, -1.0, 0.25), axis=(2.0, 2.0, 2.0), radius=0.75)
    n6 = Intersection(n4, p5)
    n7 = Union(p1, n6)
    tree = Union(p0, n7)
    return tree


# case 201, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_201():
    p0 = Cylinder(center=(-0.25, 0.75, -0.75), axis=(0.0, 1.0, 0.0), radius=0.001)
    p1 = Cone(center=(-0.75, 0.0, -0.75), axis=(2.0, 2.0, 2.0), radius=0.75)
    p2 = Box(center=(-0.649519052838329, -0.37499999999999994, -0.75), size=(0.75, 0.75, 1.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p3 = Cylinder(center=(-0.25, 0.75, -0.75), axis=(0.0, 1.0, 0.0), radius=0.001)
    n4 = Intersection(p2, p3)
    p5 = Cone(center=(0.5, -1.0, 0.25), axis=(2.0, 2.0, 2.0), radius=0.75)
    n6 = Intersection(n4, p5)
    n7 = Union(p1, n6)
    tree = Union(p0, n7)
    return tree


# case 202, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_202():
    p0 = Cylinder(center=(-0.25, 0.75, -0.75), axis=(0.0, 1.0, 0.0), radius=0.001)
    p1 = Cone(center=(0.5, -1.0, 0.25), axis=(2.0, 2.0, 2.0), radius=0.75)
    p2 = Box(center=(-0.649519052838329, -0.37499999999999994, -0.75), size=(0.75, 0.75, 1.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p3 = Cylinder(center=(-0.25, 0.75, -0.75), axis=(0.0, 1.0, 0.0), radius=0.001)
    n4 = Intersection(p2, p3)
    p5 = Cone(center=(0.5, -1.0, 0.25), axis=(2.0, 2.0, 2.0), radius=0.75)
    n6 = Intersection(n4, p5)
    n7 = Union(p1, n6)
    tree = Union(p0, n7)
    return tree


# case 206, pyvista: wrong volume, area, hausdorff, topology
# volume    13.261981 (true 12.0419316): error +1.220e+00, tessellation -2.112e-01, bound 4.770e-01 -> wrong
# area      27.6255091 (true 26.701641): error +9.239e-01, tessellation -3.059e-01 -> wrong
# hausdorff mesh->true 7.361e-01, true->mesh 1.918e-02, tessellation 1.918e-02 -> wrong
# topology  8 components, genus 6.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_206():
    p0 = Cylinder(center=(1.0, 0.5, 0.75), axis=(2.0, 0.0, 0.0), radius=2.0)
    p1 = Sphere(center=(1.0, 0.5, 0.75), radius=1.5)
    tree = Intersection(p0, p1)
    return tree


# case 207, pyvista: wrong hausdorff, topology
# volume    12.2510247 (true 12.0419316): error +2.091e-01, tessellation -2.112e-01, bound 4.770e-01 -> tessellation
# area      26.8375008 (true 26.701641): error +1.359e-01, tessellation -3.059e-01 -> tessellation
# hausdorff mesh->true 9.277e-01, true->mesh 1.841e-02, tessellation 1.841e-02 -> wrong
# topology  7 components, genus 5.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: hausdorff, topology
def case_207():
    p0 = Cylinder(center=(1.0, 0.75, 0.75), axis=(2.0, 0.0, 0.0), radius=2.0)
    p1 = Sphere(center=(1.0, 0.5, 0.75), radius=1.5)
    tree = Intersection(p0, p1)
    return tree


# case 208, pyvista: wrong topology
# volume    3.43417082 (true 3.49369403): error -5.952e-02, tessellation -4.113e-02, bound 3.561e-01 -> tessellation
# area      18.2698355 (true 18.4453133): error -1.755e-01, tessellation -2.000e-01 -> tessellation
# hausdorff mesh->true 1.438e-02, true->mesh 1.434e-02, tessellation 1.461e-02 -> tessellation
# topology  4 components, genus 2.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_208():
    p0 = Cylinder(center=(1.0, 0.75, 0.75), axis=(0.5, 0.0, 0.0), radius=2.0)
    p1 = Sphere(center=(1.0, 0.5, 0.75), radius=1.5)
    tree = Intersection(p0, p1)
    return tree


# case 210, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.76714587): error -1.767e+00, tessellation -3.947e-02, bound 3.553e-01 -> wrong
# area      0 (true 7.06858347): error -7.069e+00, tessellation -8.612e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 9.585e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_210():
    p0 = Sphere(center=(-1.0, -1.0, -1.0), radius=0.75)
    p1 = Sphere(center=(-1.0, -1.0, -1.0), radius=1.5)
    tree = Intersection(p0, p1)
    return tree


# case 213, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0654498469): error -6.545e-02, tessellation -1.462e-03, bound 4.094e-02 -> wrong
# area      0 (true 0.785398163): error -7.854e-01, tessellation -9.569e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.258e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_213():
    p0 = Sphere(center=(-1.0, -1.0, -1.0), radius=0.25)
    p1 = Sphere(center=(-1.0, -1.0, -1.0), radius=0.75)
    tree = Intersection(p0, p1)
    return tree


# case 216, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_216():
    p0 = Box(center=(-0.75, 0.5, -0.75), size=(1.0, 1.0, 0.0001))
    p1 = Ellipsoid(center=(-0.5, -1.0, 0.5), radii=(1.5, 0.75, 0.25))
    p2 = Cylinder(center=(-0.75, 0.75, -1.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Cylinder(center=(0.25, 0.0, 1.0), axis=(0.25, 0.0, 0.0), radius=0.5)
    p6 = Truncus(center=(0.25, 1.0, -0.75), axis=(1.0, 1.0, 1.0), r1=1.0, r2=2.0)
    n7 = Difference(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 217, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_217():
    p0 = Box(center=(-0.75, 0.5, -0.75), size=(1.0, 1.0, 0.0001))
    p1 = Ellipsoid(center=(-0.5, -1.0, 0.5), radii=(1.5, 0.75, 0.25))
    p2 = Cylinder(center=(-0.75, 0.75, -1.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Ellipsoid(center=(-0.5, -1.0, 0.5), radii=(1.5, 0.75, 0.25))
    p6 = Truncus(center=(0.25, 1.0, -0.75), axis=(1.0, 1.0, 1.0), r1=1.0, r2=2.0)
    n7 = Difference(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 218, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_218():
    p0 = Box(center=(-0.75, 0.5, -0.75), size=(1.0, 1.0, 0.0001))
    p1 = Ellipsoid(center=(-0.5, -1.0, 0.5), radii=(1.5, 0.75, 0.25))
    p2 = Cylinder(center=(-0.75, 0.75, -1.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Ellipsoid(center=(-0.5, -1.0, 0.5), radii=(1.5, 0.75, 0.25))
    p6 = Truncus(center=(0.25, 1.0, -0.75), axis=(1.0, 1.0, 1.0), r1=1.5, r2=2.0)
    n7 = Difference(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 219, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_219():
    p0 = Box(center=(-0.75, 0.5, -0.75), size=(1.0, 1.0, 0.0001))
    p1 = Ellipsoid(center=(-0.5, -1.0, 0.5), radii=(1.0, 0.75, 0.25))
    p2 = Cylinder(center=(-0.75, 0.75, -1.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Ellipsoid(center=(-0.5, -1.0, 0.5), radii=(1.5, 0.75, 0.25))
    p6 = Truncus(center=(0.25, 1.0, -0.75), axis=(1.0, 1.0, 1.0), r1=1.5, r2=2.0)
    n7 = Difference(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 220, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_220():
    p0 = Box(center=(-0.75, 0.5, -0.75), size=(1.0, 1.0, 0.0001))
    p1 = Ellipsoid(center=(-0.5, -1.0, 0.5), radii=(1.0, 0.75, 0.25))
    p2 = Cylinder(center=(-0.75, 0.75, -1.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Ellipsoid(center=(-0.5, 0.0, 0.5), radii=(1.5, 0.75, 0.25))
    p6 = Truncus(center=(0.25, 1.0, -0.75), axis=(1.0, 1.0, 1.0), r1=1.5, r2=2.0)
    n7 = Difference(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 221, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_221():
    p0 = Box(center=(-0.75, 0.5, -0.75), size=(1.0, 1.0, 0.0001))
    p1 = Ellipsoid(center=(-0.5, -1.0, 0.5), radii=(1.0, 0.75, 0.25))
    p2 = Cylinder(center=(-0.75, 0.75, -1.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Ellipsoid(center=(-0.5, -1.0, 0.5), radii=(1.0, 0.75, 0.25))
    p6 = Truncus(center=(0.25, 1.0, -0.75), axis=(1.0, 1.0, 1.0), r1=1.5, r2=2.0)
    n7 = Difference(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 222, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_222():
    p0 = Box(center=(-0.75, 0.5, -0.75), size=(1.0, 1.0, 0.0001))
    p1 = Ellipsoid(center=(-0.5, -1.0, 0.5), radii=(1.0, 0.75, 0.25))
    p2 = Cylinder(center=(-0.75, 0.75, -1.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Ellipsoid(center=(-0.5, -1.0, 0.5), radii=(1.0, 0.75, 0.25))
    p6 = Truncus(center=(0.25, 1.0, -0.75), axis=(1.0, 1.0, 1.0), r1=1.5, r2=2.0)
    n7 = Union(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 225, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.11276564): error -1.113e+00, tessellation -2.728e-02, bound 2.301e-01 -> wrong
# area      0 (true 7.04560802): error -7.046e+00, tessellation -8.213e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.090e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_225():
    p0 = Truncus(center=(0.0, 1.0, -0.25), axis=(1.5, 0.0, 0.0), r1=1.5, r2=1.75)
    p1 = Cylinder(center=(0.75, -0.75, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Ellipsoid(center=(1.0, -0.25, -0.25), radii=(2.0, 0.5, 0.75))
    n3 = Union(p1, p2)
    n4 = Intersection(p0, n3)
    p5 = Box(center=(0.75, 0.75, 1.0), size=(1.0, 1.0, 0.0001))
    p6 = Truncus(center=(0.0, 1.0, -0.25), axis=(1.5, 0.0, 0.0), r1=1.5, r2=1.75)
    n7 = Difference(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 227, pyvista: crashed (exit code -11)
def case_227():
    p0 = Truncus(center=(0.0, 1.0, -0.25), axis=(1.5, 0.0, 0.0), r1=1.5, r2=1.75)
    p1 = Truncus(center=(0.0, 1.0, -0.25), axis=(1.5, 0.0, 0.0), r1=1.5, r2=1.75)
    p2 = Ellipsoid(center=(1.0, -0.25, -0.25), radii=(2.0, 0.5, 0.75))
    n3 = Union(p1, p2)
    n4 = Intersection(p0, n3)
    p5 = Box(center=(0.75, 0.75, 1.0), size=(1.0, 1.0, 0.0001))
    p6 = Truncus(center=(0.0, 1.0, -0.25), axis=(1.5, 0.0, 0.0), r1=1.5, r2=1.75)
    n7 = Difference(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 228, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 22.2748244): error -2.227e+01, tessellation -1.429e-01, bound 1.429e-01 -> wrong
# area      0 (true 45.2628237): error -4.526e+01, tessellation -1.688e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 8.426e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_228():
    p0 = Cylinder(center=(-0.25, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(-0.75, 0.5, -0.75), axis=(0.6, -1.0, 2.0), radius=1.75)
    p2 = Cylinder(center=(-0.75, 0.5, -0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Union(p1, p2)
    tree = Union(p0, n3)
    return tree


# case 229, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 22.2747913): error -2.227e+01, tessellation -1.428e-01, bound 1.429e-01 -> wrong
# area      0 (true 45.2624006): error -4.526e+01, tessellation -1.684e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 8.427e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_229():
    p0 = Cylinder(center=(-0.25, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(-0.75, 0.5, -0.75), axis=(0.6, -1.0, 2.0), radius=1.75)
    p2 = Cylinder(center=(-0.25, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Union(p1, p2)
    tree = Union(p0, n3)
    return tree


# case 230, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 22.2747913): error -2.227e+01, tessellation -1.428e-01, bound 1.429e-01 -> wrong
# area      0 (true 45.2624006): error -4.526e+01, tessellation -1.684e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 8.426e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_230():
    p0 = Cylinder(center=(-0.25, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(-0.75, 0.5, -0.75), axis=(0.6, -1.0, 2.0), radius=1.75)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-0.25, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Union(n2, p3)
    return tree


# case 234, trimesh-manifold: wrong area, topology
# volume    0 (true 0): error +0.000e+00, tessellation -9.035e-21, bound 5.139e-02 -> exact
# area      0.00462400799 (true 0): error +4.624e-03, tessellation +2.099e-03 -> wrong
# hausdorff mesh->true 2.966e-03, true->mesh 0.000e+00, tessellation 2.981e-03 -> tessellation
# topology  9 components, genus 4, watertight False, winding consistent False (true: 14, genus 0, from mesh) -> wrong
# verdict   WRONG: area, topology
# case 234, pyvista: crashed (exit code -11)
def case_234():
    p0 = Cylinder(center=(0.25, 0.5, 0.25), axis=(0.0, 0.0, 0.75), radius=1.75)
    p1 = Cylinder(center=(-0.75, 0.25, 0.75), axis=(0.44999999999999996, -0.75, 1.5), radius=0.25)
    n2 = Difference(p0, p1)
    p3 = Sphere(center=(0.0, 1.0, 0.0), radius=0.25)
    n4 = Intersection(n2, p3)
    p5 = Sphere(center=(0.0, 1.0, 0.0), radius=0.25)
    n6 = Difference(n4, p5)
    p7 = Box(center=(-0.25, 0.75, -0.5), size=(1.0, 1.0, 0.0001))
    tree = Difference(n6, p7)
    return tree


# case 235, trimesh-manifold: wrong area, hausdorff, topology
# volume    0 (true 0): error +0.000e+00, tessellation +0.000e+00, bound 2.054e-02 -> exact
# area      0.00902611855 (true 0): error +9.026e-03, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 2.975e-03, true->mesh 0.000e+00, tessellation 0.000e+00 -> wrong
# topology  14 components, genus 6.5, watertight False, winding consistent False (true: 4, genus 0, from mesh) -> wrong
# verdict   WRONG: area, hausdorff, topology
# case 235, pyvista: crashed (exit code -11)
def case_235():
    p0 = Cylinder(center=(0.25, 0.5, 0.25), axis=(0.0, 0.0, 0.25), radius=1.75)
    p1 = Cylinder(center=(-0.75, 0.25, 0.75), axis=(0.44999999999999996, -0.75, 1.5), radius=0.25)
    n2 = Difference(p0, p1)
    p3 = Sphere(center=(0.0, 1.0, 0.0), radius=0.25)
    n4 = Intersection(n2, p3)
    p5 = Sphere(center=(0.0, 1.0, 0.0), radius=0.25)
    n6 = Difference(n4, p5)
    p7 = Box(center=(-0.25, 0.75, -0.5), size=(1.0, 1.0, 0.0001))
    tree = Difference(n6, p7)
    return tree


# case 236, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_236():
    p0 = Cylinder(center=(0.25, 0.5, 0.25), axis=(0.0, 0.0, 0.25), radius=1.75)
    p1 = Cylinder(center=(0.25, 0.5, 0.25), axis=(0.0, 0.0, 0.25), radius=1.75)
    n2 = Difference(p0, p1)
    p3 = Sphere(center=(0.0, 1.0, 0.0), radius=0.25)
    n4 = Intersection(n2, p3)
    p5 = Sphere(center=(0.0, 1.0, 0.0), radius=0.25)
    n6 = Difference(n4, p5)
    p7 = Box(center=(-0.25, 0.75, -0.5), size=(1.0, 1.0, 0.0001))
    tree = Difference(n6, p7)
    return tree


# case 237, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_237():
    p0 = Cylinder(center=(0.25, 0.5, 0.25), axis=(0.0, 0.0, 0.25), radius=1.75)
    p1 = Cylinder(center=(0.25, 0.5, 0.25), axis=(0.0, 0.0, 0.25), radius=1.75)
    n2 = Difference(p0, p1)
    p3 = Sphere(center=(0.0, 1.0, 0.0), radius=0.25)
    n4 = Intersection(n2, p3)
    p5 = Cylinder(center=(0.25, 0.5, 0.25), axis=(0.0, 0.0, 0.25), radius=1.75)
    n6 = Difference(n4, p5)
    p7 = Box(center=(-0.25, 0.75, -0.5), size=(1.0, 1.0, 0.0001))
    tree = Difference(n6, p7)
    return tree


# case 238, trimesh-manifold: wrong volume
# volume    10.941916 (true 11.1919238): error -2.500e-01, tessellation -2.500e-01, bound 2.500e-01 -> wrong
# area      31.4905992 (true 31.8694163): error -3.788e-01, tessellation -3.788e-01 -> tessellation
# hausdorff mesh->true 1.736e-02, true->mesh 1.560e-02, tessellation 1.757e-02 -> tessellation
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: volume
# case 238, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 11.1919238): error -1.119e+01, tessellation -2.500e-01, bound 2.500e-01 -> wrong
# area      0 (true 31.8694163): error -3.187e+01, tessellation -3.788e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.757e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_238():
    p0 = Sphere(center=(1.0, -0.25, 0.75), radius=0.75)
    p1 = Ellipsoid(center=(-0.5, -0.25, -0.25), radii=(0.75, 1.5, 2.0))
    tree = Union(p0, p1)
    return tree


# case 247, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.523598776): error -5.236e-01, tessellation -1.170e-02, bound 1.170e-02 -> wrong
# area      0 (true 3.14159265): error -3.142e+00, tessellation -3.827e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 5.994e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_247():
    p0 = Sphere(center=(0.75, -0.25, 0.0), radius=0.5)
    p1 = Cylinder(center=(-0.5, -0.75, -0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(p0, p1)
    return tree


# case 248, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0654498469): error -6.545e-02, tessellation -1.462e-03, bound 1.467e-03 -> wrong
# area      0 (true 0.785398163): error -7.854e-01, tessellation -9.569e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.008e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_248():
    p0 = Sphere(center=(0.75, -0.25, 0.0), radius=0.25)
    p1 = Cylinder(center=(-0.5, -0.75, -0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(p0, p1)
    return tree


# case 249, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0654498469): error -6.545e-02, tessellation -1.462e-03, bound 1.467e-03 -> wrong
# area      0 (true 0.785398163): error -7.854e-01, tessellation -9.569e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.127e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_249():
    p0 = Sphere(center=(0.75, -0.25, 0.0), radius=0.25)
    p1 = Cylinder(center=(-0.75, -0.75, -0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(p0, p1)
    return tree


# case 253, pyvista: wrong area, hausdorff, topology
# volume    0.000669389842 (true 0.000671990026): error -2.600e-06, tessellation -2.600e-06, bound 1.007e-05 -> tessellation
# area      1.43075034 (true 1.34680085): error +8.395e-02, tessellation -4.885e-03 -> wrong
# hausdorff mesh->true 3.449e-04, true->mesh 4.058e-02, tessellation 1.757e-03 -> wrong
# topology  3 components, genus 10, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_253():
    p0 = Cylinder(center=(0.0, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(0.75, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(p0, p1)
    return tree


# case 255, trimesh-manifold: wrong volume
# volume    1.75591823 (true 1.76725131): error -1.133e-02, tessellation -1.133e-02, bound 1.133e-02 -> wrong
# area      10.22772 (true 10.2579698): error -3.025e-02, tessellation -3.025e-02 -> tessellation
# hausdorff mesh->true 3.611e-03, true->mesh 3.611e-03, tessellation 3.611e-03 -> tessellation
# topology  3 components, genus 0, watertight True, winding consistent True (true: 3, genus 0) -> exact
# verdict   WRONG: volume
def case_255():
    p0 = Cylinder(center=(0.5, -0.75, 1.0), axis=(1.0, 1.0, 1.0), radius=0.001)
    p1 = Box(center=(-1.0, 0.25, 0.75), size=(1.0, 1.0, 0.0001))
    p2 = Cylinder(center=(0.75, -0.5, -0.75), axis=(0.0, 0.0, 1.0), radius=0.75)
    p3 = Box(center=(-1.0, 1.0, -0.75), size=(1.0, 1.0, 0.0001))
    n4 = Difference(p2, p3)
    n5 = Union(p1, n4)
    tree = Union(p0, n5)
    return tree


# case 256, trimesh-manifold: wrong volume
# volume    1.75591823 (true 1.76725131): error -1.133e-02, tessellation -1.133e-02, bound 1.133e-02 -> wrong
# area      10.22772 (true 10.2579698): error -3.025e-02, tessellation -3.025e-02 -> tessellation
# hausdorff mesh->true 3.611e-03, true->mesh 3.611e-03, tessellation 3.611e-03 -> tessellation
# topology  3 components, genus 0, watertight True, winding consistent True (true: 3, genus 0) -> exact
# verdict   WRONG: volume
def case_256():
    p0 = Cylinder(center=(0.5, -1.0, 1.0), axis=(1.0, 1.0, 1.0), radius=0.001)
    p1 = Box(center=(-1.0, 0.25, 0.75), size=(1.0, 1.0, 0.0001))
    p2 = Cylinder(center=(0.75, -0.5, -0.75), axis=(0.0, 0.0, 1.0), radius=0.75)
    p3 = Box(center=(-1.0, 1.0, -0.75), size=(1.0, 1.0, 0.0001))
    n4 = Difference(p2, p3)
    n5 = Union(p1, n4)
    tree = Union(p0, n5)
    return tree


# case 257, trimesh-manifold: wrong volume
# volume    1.75591823 (true 1.76725131): error -1.133e-02, tessellation -1.133e-02, bound 1.133e-02 -> wrong
# area      10.22772 (true 10.2579698): error -3.025e-02, tessellation -3.025e-02 -> tessellation
# hausdorff mesh->true 3.611e-03, true->mesh 3.611e-03, tessellation 3.611e-03 -> tessellation
# topology  3 components, genus 0, watertight True, winding consistent True (true: 3, genus 0) -> exact
# verdict   WRONG: volume
def case_257():
    p0 = Cylinder(center=(0.5, -1.0, 1.0), axis=(1.0, 1.0, 1.0), radius=0.001)
    p1 = Box(center=(-1.0, 0.25, 0.75), size=(1.0, 1.0, 0.0001))
    p2 = Cylinder(center=(0.75, -0.5, -0.75), axis=(0.0, 0.0, 1.0), radius=0.75)
    p3 = Box(center=(-1.0, 0.25, 0.75), size=(1.0, 1.0, 0.0001))
    n4 = Difference(p2, p3)
    n5 = Union(p1, n4)
    tree = Union(p0, n5)
    return tree


# case 258, pyvista: wrong volume, hausdorff, topology
# volume    2.23047879 (true 2.27393505): error -4.346e-02, tessellation -4.227e-02, bound 4.275e-02 -> wrong
# area      14.8930829 (true 14.8891527): error +3.930e-03, tessellation -1.101e-01 -> exact
# hausdorff mesh->true 3.397e-01, true->mesh 8.690e-03, tessellation 9.511e-03 -> wrong
# topology  5 components, genus 5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, hausdorff, topology
def case_258():
    p0 = Box(center=(0.5, -1.0, 1.0), size=(1.0, 1.0, 0.0001))
    p1 = Cone(center=(0.0, -1.0, 0.25), axis=(0.5, 0.5, 0.5), radius=0.75)
    p2 = Sphere(center=(-0.75, 0.0, 1.0), radius=0.75)
    p3 = Box(center=(-1.0, 0.25, 0.75), size=(1.0, 1.0, 0.0001))
    n4 = Difference(p2, p3)
    n5 = Union(p1, n4)
    tree = Union(p0, n5)
    return tree


# case 260, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_260():
    p0 = Cylinder(center=(1.0, 0.5, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(0.25, -0.5, -0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Ellipsoid(center=(-1.0, 0.0, 0.75), radii=(1.5, 0.75, 2.0))
    p3 = Cylinder(center=(1.0, 0.75, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n4 = Intersection(p2, p3)
    n5 = Intersection(p1, n4)
    tree = Union(p0, n5)
    return tree


# case 261, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_261():
    p0 = Cylinder(center=(1.0, 0.5, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(1.0, 0.75, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Ellipsoid(center=(-1.0, 0.0, 0.75), radii=(1.5, 0.75, 2.0))
    p3 = Cylinder(center=(1.0, 0.75, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n4 = Intersection(p2, p3)
    n5 = Intersection(p1, n4)
    tree = Union(p0, n5)
    return tree


# case 262, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_262():
    p0 = Cylinder(center=(0.0, 0.5, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(1.0, 0.75, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Ellipsoid(center=(-1.0, 0.0, 0.75), radii=(1.5, 0.75, 2.0))
    p3 = Cylinder(center=(1.0, 0.75, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n4 = Intersection(p2, p3)
    n5 = Intersection(p1, n4)
    tree = Union(p0, n5)
    return tree


# case 267, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.0654498469): error -6.545e-02, tessellation -1.462e-03, bound 1.880e-01 -> tessellation
# area      0 (true 0.785398163): error -7.854e-01, tessellation -9.569e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.157e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_267():
    p0 = Cylinder(center=(0.0, 0.0, 0.0), axis=(0.6, -1.0, 2.0), radius=2.0)
    p1 = Sphere(center=(0.25, 0.75, -0.5), radius=0.25)
    tree = Intersection(p0, p1)
    return tree


# case 268, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.0654498469): error -6.545e-02, tessellation -1.462e-03, bound 1.880e-01 -> tessellation
# area      0 (true 0.785398163): error -7.854e-01, tessellation -9.569e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.039e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_268():
    p0 = Cylinder(center=(0.25, 0.75, -0.5), axis=(0.6, -1.0, 2.0), radius=2.0)
    p1 = Sphere(center=(0.25, 0.75, -0.5), radius=0.25)
    tree = Intersection(p0, p1)
    return tree


# case 269, pyvista: wrong topology
# volume    4.09627751 (true 4.18936991): error -9.309e-02, tessellation -9.357e-02, bound 9.358e-02 -> tessellation
# area      13.5719098 (true 13.7078376): error -1.359e-01, tessellation -1.388e-01 -> tessellation
# hausdorff mesh->true 1.194e-02, true->mesh 1.194e-02, tessellation 1.194e-02 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_269():
    p0 = Sphere(center=(0.25, 0.75, -0.5), radius=1.0)
    p1 = Cylinder(center=(0.0, 0.0, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 272, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 4.1887902): error -4.189e+00, tessellation -9.357e-02, bound 9.503e-02 -> wrong
# area      0 (true 12.5663706): error -1.257e+01, tessellation -1.531e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.191e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_272():
    p0 = Sphere(center=(0.25, 0.25, -0.5), radius=1.0)
    p1 = Sphere(center=(0.25, 0.75, -0.5), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 274, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 8.41714899): error -8.417e+00, tessellation -5.398e-02, bound 5.398e-02 -> wrong
# area      0 (true 25.6906755): error -2.569e+01, tessellation -9.455e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 6.678e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_274():
    p0 = Truncus(center=(-1.0, 0.25, -0.5), axis=(2.0, 0.0, 0.0), r1=1.5, r2=0.75)
    p1 = Cylinder(center=(-1.0, -0.5, 1.0), axis=(0.22499999999999998, -0.375, 0.75), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 275, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 8.39394287): error -8.394e+00, tessellation -5.383e-02, bound 5.383e-02 -> wrong
# area      0 (true 25.5050266): error -2.551e+01, tessellation -9.425e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 6.673e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_275():
    p0 = Truncus(center=(-1.0, 0.25, -0.5), axis=(2.0, 0.0, 0.0), r1=1.5, r2=0.75)
    p1 = Cylinder(center=(-1.0, -0.5, 1.0), axis=(0.75, 0.0, 0.0), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 276, pyvista: wrong topology
# volume    14.3871262 (true 14.4750247): error -8.790e-02, tessellation -9.283e-02, bound 9.285e-02 -> tessellation
# area      36.8234755 (true 36.7813314): error +4.214e-02, tessellation -1.353e-01 -> tessellation
# hausdorff mesh->true 7.222e-03, true->mesh 7.221e-03, tessellation 7.223e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_276():
    p0 = Cylinder(center=(-1.0, 0.25, -0.5), axis=(2.0, 0.0, 0.0), radius=1.5)
    p1 = Cone(center=(0.5, -1.0, -0.5), axis=(0.15, -0.25, 0.5), radius=0.75)
    tree = Union(p0, p1)
    return tree


# case 277, pyvista: wrong hausdorff, topology
# volume    16.5500903 (true 16.6578964): error -1.078e-01, tessellation -1.055e-01, bound 1.071e-01 -> tessellation
# area      38.7503136 (true 38.8720284): error -1.217e-01, tessellation -1.242e-01 -> tessellation
# hausdorff mesh->true 1.982e-02, true->mesh 7.223e-03, tessellation 7.223e-03 -> wrong
# topology  1 components, genus 1, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: hausdorff, topology
def case_277():
    p0 = Cylinder(center=(-1.0, 0.25, -0.5), axis=(0.6, -1.0, 2.0), radius=1.5)
    p1 = Cone(center=(0.5, -1.0, -0.5), axis=(0.15, -0.25, 0.5), radius=0.75)
    tree = Union(p0, p1)
    return tree


# case 279, pyvista: crashed (exit code -11)
def case_279():
    p0 = Cone(center=(0.5, -1.0, -0.5), axis=(0.15, -0.25, 0.5), radius=0.75)
    p1 = Cone(center=(0.5, -1.0, -0.5), axis=(0.15, -0.25, 0.5), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 281, pyvista: wrong topology
# volume    3.73984083 (true 3.80854547): error -6.870e-02, tessellation -6.828e-02, bound 2.186e-01 -> tessellation
# area      14.2785473 (true 14.3922371): error -1.137e-01, tessellation -1.324e-01 -> tessellation
# hausdorff mesh->true 1.493e-02, true->mesh 1.503e-02, tessellation 1.503e-02 -> tessellation
# topology  7 components, genus 5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_281():
    p0 = Truncus(center=(1.0, -0.5, 0.0), axis=(0.0, 0.0, 1.5), r1=0.25, r2=1.75)
    p1 = Sphere(center=(1.0, -0.25, -0.75), radius=1.25)
    tree = Intersection(p0, p1)
    return tree


# case 282, trimesh-manifold: wrong topology
# volume    3.90190303 (true 3.95398133): error -5.208e-02, tessellation -5.208e-02, bound 2.186e-01 -> tessellation
# area      13.5988198 (true 13.7349329): error -1.361e-01, tessellation -1.361e-01 -> tessellation
# hausdorff mesh->true 1.475e-02, true->mesh 1.440e-02, tessellation 1.573e-02 -> tessellation
# topology  2 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
# case 282, pyvista: wrong topology
# volume    3.90190305 (true 3.95398133): error -5.208e-02, tessellation -5.208e-02, bound 2.186e-01 -> tessellation
# area      13.5985855 (true 13.7349329): error -1.363e-01, tessellation -1.361e-01 -> tessellation
# hausdorff mesh->true 1.605e-02, true->mesh 1.440e-02, tessellation 1.573e-02 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_282():
    p0 = Truncus(center=(1.0, -0.5, 0.0), axis=(0.0, 0.0, 1.5), r1=0.25, r2=1.75)
    p1 = Sphere(center=(1.0, -0.25, 0.0), radius=1.25)
    tree = Intersection(p0, p1)
    return tree


# case 283, pyvista: wrong topology
# volume    4.00346807 (true 4.05568799): error -5.222e-02, tessellation -5.222e-02, bound 2.186e-01 -> tessellation
# area      13.7347939 (true 13.861352): error -1.266e-01, tessellation -1.263e-01 -> tessellation
# hausdorff mesh->true 1.546e-02, true->mesh 1.432e-02, tessellation 1.459e-02 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_283():
    p0 = Truncus(center=(1.0, -0.25, 0.0), axis=(0.0, 0.0, 1.5), r1=0.25, r2=1.75)
    p1 = Sphere(center=(1.0, -0.25, 0.0), radius=1.25)
    tree = Intersection(p0, p1)
    return tree


# case 284, pyvista: wrong topology
# volume    1.86001372 (true 1.90278254): error -4.277e-02, tessellation -4.094e-02, bound 2.186e-01 -> tessellation
# area      9.62474299 (true 9.74407489): error -1.193e-01, tessellation -1.284e-01 -> tessellation
# hausdorff mesh->true 1.493e-02, true->mesh 1.602e-02, tessellation 1.602e-02 -> tessellation
# topology  4 components, genus 2.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_284():
    p0 = Truncus(center=(1.0, -0.25, 0.0), axis=(0.0, 0.0, 1.5), r1=0.25, r2=1.75)
    p1 = Sphere(center=(1.0, 1.0, 0.0), radius=1.25)
    tree = Intersection(p0, p1)
    return tree


# case 285, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.60757553): error -1.608e+00, tessellation -4.187e-02, bound 4.187e-02 -> wrong
# area      0 (true 13.1224037): error -1.312e+01, tessellation -9.416e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 5.576e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 1) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_285():
    p0 = Sphere(center=(1.0, -0.25, 0.0), radius=0.25)
    p1 = Torus(center=(0.25, 0.0, 0.0), axis=(0.25916052767440806, -0.4319342127906801, 0.8638684255813602), major=1.25, minor=0.25)
    tree = Union(p0, p1)
    return tree


# case 286, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 13.0247031): error -1.302e+01, tessellation -3.536e-01, bound 3.536e-01 -> wrong
# area      0 (true 43.101327): error -4.310e+01, tessellation -3.259e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.471e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 1) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_286():
    p0 = Torus(center=(1.0, -0.25, 0.0), axis=(0.0, 1.0, 0.0), major=1.75, minor=0.6124999999999999)
    p1 = Sphere(center=(0.0, 1.0, 1.0), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 287, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 13.0247031): error -1.302e+01, tessellation -3.536e-01, bound 3.536e-01 -> wrong
# area      0 (true 43.101327): error -4.310e+01, tessellation -3.259e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.471e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 1) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_287():
    p0 = Torus(center=(0.0, 1.0, 1.0), axis=(0.0, 1.0, 0.0), major=1.75, minor=0.6124999999999999)
    p1 = Sphere(center=(0.0, 1.0, 1.0), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 294, pyvista: wrong topology
# volume    0.000813814988 (true 0.00192600906): error -1.112e-03, tessellation -1.077e-03, bound 3.292e-01 -> tessellation
# area      0.109409902 (true 0.176484535): error -6.707e-02, tessellation -6.714e-02 -> tessellation
# hausdorff mesh->true 1.527e-02, true->mesh 5.056e-02, tessellation 5.056e-02 -> tessellation
# topology  2 components, genus 1, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_294():
    p0 = Torus(center=(0.25, 0.5, 1.0), axis=(0.0, 0.0, 1.0), major=2.0, minor=0.4)
    p1 = Ellipsoid(center=(0.0, -0.5, -0.75), radii=(1.75, 0.5, 2.0))
    tree = Intersection(p0, p1)
    return tree


# case 297, pyvista: wrong topology
# volume    19.500115 (true 20.0344828): error -5.344e-01, tessellation -5.344e-01, bound 5.994e-01 -> tessellation
# area      56.7529171 (true 57.0886108): error -3.357e-01, tessellation -3.359e-01 -> tessellation
# hausdorff mesh->true 1.892e-02, true->mesh 1.906e-02, tessellation 1.906e-02 -> tessellation
# topology  1 components, genus 2, watertight True, winding consistent False (true: 1, genus 2) -> wrong
# verdict   WRONG: topology
def case_297():
    p0 = Torus(center=(-0.5, 0.25, -1.0), axis=(0.0, 1.0, 0.0), major=1.5, minor=0.75)
    p1 = Torus(center=(-0.5, -0.25, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.25, minor=0.4375)
    tree = Union(p0, p1)
    return tree


# case 298, pyvista: wrong topology
# volume    19.5637884 (true 20.102547): error -5.388e-01, tessellation -5.399e-01, bound 5.994e-01 -> tessellation
# area      57.9031194 (true 58.2585156): error -3.554e-01, tessellation -3.561e-01 -> tessellation
# hausdorff mesh->true 1.816e-02, true->mesh 1.876e-02, tessellation 1.888e-02 -> tessellation
# topology  1 components, genus 2, watertight True, winding consistent False (true: 1, genus 2) -> wrong
# verdict   WRONG: topology
def case_298():
    p0 = Torus(center=(-0.5, 0.25, -1.0), axis=(0.0, 1.0, 0.0), major=1.5, minor=0.75)
    p1 = Torus(center=(1.0, -0.25, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.25, minor=0.4375)
    tree = Union(p0, p1)
    return tree


# case 301, pyvista: wrong topology
# volume    8.95626172 (true 9.19222628): error -2.360e-01, tessellation -2.354e-01, bound 2.567e-01 -> tessellation
# area      39.2285713 (true 39.3970654): error -1.685e-01, tessellation -1.689e-01 -> tessellation
# hausdorff mesh->true 1.019e-02, true->mesh 1.042e-02, tessellation 1.049e-02 -> tessellation
# topology  1 components, genus 4.5, watertight False, winding consistent True (true: 1, genus 3) -> wrong
# verdict   WRONG: topology
def case_301():
    p0 = Torus(center=(1.0, -0.25, 1.0), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.25, minor=0.4375)
    p1 = Torus(center=(1.0, 1.0, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.25, minor=0.4375)
    tree = Union(p0, p1)
    return tree


# case 303, pyvista: wrong topology
# volume    15.1682937 (true 15.4860983): error -3.178e-01, tessellation -3.175e-01, bound 3.332e-01 -> tessellation
# area      33.3903875 (true 33.7144486): error -3.241e-01, tessellation -3.201e-01 -> tessellation
# hausdorff mesh->true 1.882e-02, true->mesh 1.806e-02, tessellation 1.806e-02 -> tessellation
# topology  1 components, genus 1, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_303():
    p0 = Sphere(center=(-0.25, 0.0, -1.0), radius=1.5)
    p1 = Cylinder(center=(0.0, 1.0, 0.0), axis=(2.0, 2.0, 2.0), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 305, pyvista: wrong topology
# volume    14.753649 (true 15.0635643): error -3.099e-01, tessellation -3.098e-01, bound 3.332e-01 -> tessellation
# area      31.7304014 (true 32.0355436): error -3.051e-01, tessellation -3.002e-01 -> tessellation
# hausdorff mesh->true 1.801e-02, true->mesh 1.797e-02, tessellation 1.797e-02 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_305():
    p0 = Sphere(center=(0.0, 1.0, 0.0), radius=1.5)
    p1 = Cylinder(center=(0.0, 0.0, 0.0), axis=(2.0, 2.0, 2.0), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 306, pyvista: wrong topology
# volume    14.7537051 (true 15.0635643): error -3.099e-01, tessellation -3.098e-01, bound 3.332e-01 -> tessellation
# area      31.7279443 (true 32.0355436): error -3.076e-01, tessellation -3.002e-01 -> tessellation
# hausdorff mesh->true 1.875e-02, true->mesh 1.864e-02, tessellation 1.922e-02 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_306():
    p0 = Sphere(center=(0.0, 0.0, 0.0), radius=1.5)
    p1 = Cylinder(center=(0.0, 1.0, 0.0), axis=(2.0, 2.0, 2.0), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 308, trimesh-manifold: wrong topology
# volume    10.8130034 (true 10.8827772): error -6.977e-02, tessellation -6.977e-02, bound 8.724e-02 -> tessellation
# area      27.973536 (true 28.0487448): error -7.521e-02, tessellation -7.521e-02 -> tessellation
# hausdorff mesh->true 4.815e-03, true->mesh 4.812e-03, tessellation 4.815e-03 -> tessellation
# topology  18 components, genus 10.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
# case 308, pyvista: wrong volume, area, hausdorff, topology
# volume    9.7671923 (true 10.8827772): error -1.116e+00, tessellation -6.977e-02, bound 8.724e-02 -> wrong
# area      26.2573444 (true 28.0487448): error -1.791e+00, tessellation -7.521e-02 -> wrong
# hausdorff mesh->true 4.813e-03, true->mesh 3.052e-01, tessellation 4.815e-03 -> wrong
# topology  2 components, genus 2.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_308():
    p0 = Cylinder(center=(0.0, 1.0, 0.0), axis=(2.0, 2.0, 2.0), radius=0.5)
    p1 = Cylinder(center=(0.0, 1.0, 0.0), axis=(2.0, 2.0, 2.0), radius=1.0)
    tree = Union(p0, p1)
    return tree


# case 309, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.409061543): error -4.091e-01, tessellation -2.623e-03, bound 3.883e-03 -> wrong
# area      0 (true 9.91468922): error -9.915e+00, tessellation -6.266e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.755e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_309():
    p0 = Cone(center=(-1.0, 0.25, 1.0), axis=(0.25, 0.0, 0.0), radius=1.25)
    p1 = Cone(center=(-0.25, -1.0, 1.0), axis=(0.0, 0.0, 0.75), radius=0.5)
    tree = Difference(p0, p1)
    return tree


# case 311, pyvista: crashed (exit code -11)
def case_311():
    p0 = Cone(center=(-1.0, 0.25, 1.0), axis=(0.25, 0.0, 0.0), radius=1.25)
    p1 = Cone(center=(-1.0, 0.25, 1.0), axis=(0.25, 0.0, 0.0), radius=1.0)
    tree = Difference(p0, p1)
    return tree


# case 313, pyvista: wrong volume, hausdorff, topology
# volume    0.970572346 (true 0.889646887): error +8.093e-02, tessellation -5.644e-03, bound 8.395e-03 -> wrong
# area      9.04710887 (true 8.99793698): error +4.917e-02, tessellation -4.976e-02 -> tessellation
# hausdorff mesh->true 2.652e-01, true->mesh 3.369e-03, tessellation 3.369e-03 -> wrong
# topology  4 components, genus 2, watertight False, winding consistent False (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, hausdorff, topology
def case_313():
    p0 = Cone(center=(-1.0, 0.25, 1.0), axis=(1.0, 0.0, 0.0), radius=1.0)
    p1 = Cone(center=(-1.0, 0.25, 1.0), axis=(0.25, 0.0, 0.0), radius=1.0)
    tree = Difference(p0, p1)
    return tree


# case 315, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.04719755): error -1.047e+00, tessellation -6.716e-03, bound 1.343e-02 -> wrong
# area      0 (true 7.58447559): error -7.584e+00, tessellation -3.795e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.266e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_315():
    p0 = Cone(center=(-1.0, 0.25, -1.0), axis=(1.0, 0.0, 0.0), radius=1.0)
    p1 = Cone(center=(-1.0, 0.25, 1.0), axis=(1.0, 0.0, 0.0), radius=1.0)
    tree = Difference(p0, p1)
    return tree


# case 319, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.39833581): error -1.398e+00, tessellation -2.768e-02, bound 1.872e-01 -> wrong
# area      0 (true 7.07825228): error -7.078e+00, tessellation -8.795e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 9.046e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_319():
    p0 = Sphere(center=(1.0, -0.5, 0.75), radius=0.75)
    p1 = Truncus(center=(1.0, 1.0, 0.25), axis=(0.6, -1.0, 2.0), r1=1.0, r2=1.5)
    n2 = Difference(p0, p1)
    p3 = Truncus(center=(1.0, 1.0, 0.25), axis=(0.6, -1.0, 2.0), r1=1.0, r2=1.5)
    tree = Difference(n2, p3)
    return tree


# case 323, trimesh-manifold: wrong area, topology
# volume    1.50229267e-09 (true 0): error +1.502e-09, tessellation +0.000e+00, bound 1.251e-01 -> exact
# area      0.589244434 (true 0): error +5.892e-01, tessellation +3.150e-01 -> wrong
# hausdorff mesh->true 3.428e-03, true->mesh 0.000e+00, tessellation 3.391e-03 -> tessellation
# topology  9 components, genus 5, watertight False, winding consistent False (true: 0, genus 0) -> wrong
# verdict   WRONG: area, topology
def case_323():
    p0 = Truncus(center=(-0.75, 0.25, -0.25), axis=(0.0, 0.0, 0.5), r1=2.0, r2=1.5)
    p1 = Cone(center=(0.5, 0.5, 0.0), axis=(1.75, 0.0, 0.0), radius=2.0)
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.0, -0.75, -0.75), size=(1.0, 1.0, 0.0001))
    p4 = Cone(center=(0.5, 0.5, 0.0), axis=(1.75, 0.0, 0.0), radius=2.0)
    n5 = Union(p3, p4)
    tree = Intersection(n2, n5)
    return tree


# case 324, pyvista: wrong topology
# volume    1.54951485 (true 1.55429452): error -4.780e-03, tessellation -5.370e-03, bound 1.251e-01 -> tessellation
# area      10.2801361 (true 10.304407): error -2.427e-02, tessellation -2.899e-02 -> tessellation
# hausdorff mesh->true 5.566e-03, true->mesh 6.038e-03, tessellation 6.064e-03 -> tessellation
# topology  1 components, genus 1, watertight False, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_324():
    p0 = Truncus(center=(-0.75, 0.25, -0.25), axis=(0.0, 0.0, 0.5), r1=2.0, r2=1.5)
    p1 = Cone(center=(0.5, 0.5, 0.0), axis=(1.75, 0.0, 0.0), radius=2.0)
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.0, -0.75, -0.75), size=(1.0, 1.0, 0.0001))
    p4 = Cone(center=(-0.75, 0.25, -0.25), axis=(1.75, 0.0, 0.0), radius=2.0)
    n5 = Union(p3, p4)
    tree = Intersection(n2, n5)
    return tree


# case 325, trimesh-manifold: wrong topology
# volume    4.80692176 (true 4.82625871): error -1.934e-02, tessellation -1.934e-02, bound 2.027e-01 -> tessellation
# area      18.9529045 (true 19.0122444): error -5.934e-02, tessellation -5.934e-02 -> tessellation
# hausdorff mesh->true 8.474e-03, true->mesh 8.551e-03, tessellation 8.551e-03 -> tessellation
# topology  3 components, genus 1, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
# case 325, pyvista: wrong area, hausdorff, topology
# volume    4.79046277 (true 4.82625871): error -3.580e-02, tessellation -1.934e-02, bound 2.027e-01 -> tessellation
# area      19.3635591 (true 19.0122444): error +3.513e-01, tessellation -5.934e-02 -> wrong
# hausdorff mesh->true 2.484e-01, true->mesh 8.551e-03, tessellation 8.551e-03 -> wrong
# topology  4 components, genus 5.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_325():
    p0 = Truncus(center=(-0.75, 0.25, -0.25), axis=(0.0, 0.0, 1.75), r1=2.0, r2=1.5)
    p1 = Cone(center=(0.5, 0.5, 0.0), axis=(1.75, 0.0, 0.0), radius=2.0)
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.0, -0.75, -0.75), size=(1.0, 1.0, 0.0001))
    p4 = Cone(center=(-0.75, 0.25, -0.25), axis=(1.75, 0.0, 0.0), radius=2.0)
    n5 = Union(p3, p4)
    tree = Intersection(n2, n5)
    return tree


# case 326, trimesh-manifold: wrong topology
# volume    4.98624518 (true 5.00751319): error -2.127e-02, tessellation -2.127e-02, bound 1.560e-01 -> tessellation
# area      18.4007084 (true 18.4591612): error -5.845e-02, tessellation -5.845e-02 -> tessellation
# hausdorff mesh->true 8.013e-03, true->mesh 7.741e-03, tessellation 8.203e-03 -> tessellation
# topology  3 components, genus 1, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
# case 326, pyvista: wrong area, hausdorff, topology
# volume    4.96667451 (true 5.00751319): error -4.084e-02, tessellation -2.127e-02, bound 1.560e-01 -> tessellation
# area      18.7788589 (true 18.4591612): error +3.197e-01, tessellation -5.845e-02 -> wrong
# hausdorff mesh->true 2.484e-01, true->mesh 7.741e-03, tessellation 8.203e-03 -> wrong
# topology  10 components, genus 9.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_326():
    p0 = Truncus(center=(-0.75, 0.25, -0.25), axis=(0.0, 0.0, 1.75), r1=2.0, r2=1.5)
    p1 = Box(center=(0.5, 0.5, 0.0), size=(1.0, 1.0, 0.0001))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(0.0, 0.0, 0.0), axis=(0.0, 0.0, 0.25), radius=0.25)
    p4 = Cone(center=(-0.75, 0.25, -0.25), axis=(1.75, 0.0, 0.0), radius=2.0)
    n5 = Union(p3, p4)
    tree = Intersection(n2, n5)
    return tree


# case 327, trimesh-manifold: wrong topology
# volume    5.01602517 (true 5.03753121): error -2.151e-02, tessellation -2.151e-02, bound 1.560e-01 -> tessellation
# area      18.8894116 (true 18.9493422): error -5.993e-02, tessellation -5.993e-02 -> tessellation
# hausdorff mesh->true 7.440e-03, true->mesh 8.406e-03, tessellation 8.406e-03 -> tessellation
# topology  3 components, genus 1, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
# case 327, pyvista: wrong area, hausdorff, topology
# volume    4.99644434 (true 5.03753121): error -4.109e-02, tessellation -2.151e-02, bound 1.560e-01 -> tessellation
# area      19.2774969 (true 18.9493422): error +3.282e-01, tessellation -5.993e-02 -> wrong
# hausdorff mesh->true 5.000e-01, true->mesh 8.406e-03, tessellation 8.406e-03 -> wrong
# topology  13 components, genus 12.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_327():
    p0 = Truncus(center=(-0.75, 0.25, -0.25), axis=(0.0, 0.0, 1.75), r1=2.0, r2=1.5)
    p1 = Box(center=(0.5, 0.5, 0.0), size=(1.0, 1.0, 0.0001))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(0.25, 0.0, 0.0), axis=(0.0, 0.0, 0.25), radius=0.25)
    p4 = Cone(center=(-0.75, 0.25, -0.25), axis=(1.75, 0.0, 0.0), radius=2.0)
    n5 = Union(p3, p4)
    tree = Intersection(n2, n5)
    return tree


# case 328, pyvista: wrong area, hausdorff, topology
# volume    4.48341734 (true 4.47935998): error +4.057e-03, tessellation -2.040e-02, bound 1.560e-01 -> tessellation
# area      18.467633 (true 18.2485993): error +2.190e-01, tessellation -5.617e-02 -> wrong
# hausdorff mesh->true 5.000e-01, true->mesh 7.840e-03, tessellation 8.301e-03 -> wrong
# topology  9 components, genus 9, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_328():
    p0 = Truncus(center=(-0.75, 0.25, -0.25), axis=(0.0, 0.0, 1.75), r1=2.0, r2=1.5)
    p1 = Box(center=(0.5, 0.5, 0.0), size=(1.0, 1.0, 0.0001))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(0.25, 0.0, 0.0), axis=(0.0, 0.0, 0.25), radius=0.25)
    p4 = Cone(center=(-0.75, 0.25, -0.75), axis=(1.75, 0.0, 0.0), radius=2.0)
    n5 = Union(p3, p4)
    tree = Intersection(n2, n5)
    return tree


# case 332, trimesh-manifold: wrong topology
# volume    0.225833379 (true 0.227291026): error -1.458e-03, tessellation -1.458e-03, bound 7.288e-03 -> tessellation
# area      2.46842693 (true 2.47996043): error -1.153e-02, tessellation -1.153e-02 -> tessellation
# hausdorff mesh->true 2.407e-03, true->mesh 2.407e-03, tessellation 2.408e-03 -> tessellation
# topology  2 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
# case 332, pyvista: wrong volume, area, hausdorff, topology
# volume    0.538948607 (true 0.227291026): error +3.117e-01, tessellation -1.458e-03, bound 7.288e-03 -> wrong
# area      4.07143367 (true 2.47996043): error +1.591e+00, tessellation -1.153e-02 -> wrong
# hausdorff mesh->true 4.341e-01, true->mesh 2.407e-03, tessellation 2.408e-03 -> wrong
# topology  36 components, genus 63.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_332():
    p0 = Truncus(center=(0.25, -0.75, -0.25), axis=(0.3, -0.5, 1.0), r1=0.5, r2=0.5)
    p1 = Truncus(center=(0.25, -0.75, -0.25), axis=(0.075, -0.125, 0.25), r1=0.5, r2=0.5)
    tree = Intersection(p0, p1)
    return tree


# case 336, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_336():
    p0 = Cylinder(center=(-0.25, 1.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Torus(center=(0.0, -0.5, 0.0), axis=(1.0, 0.0, 0.0), major=1.5, minor=0.5249999999999999)
    n2 = Intersection(p0, p1)
    p3 = Cone(center=(1.0, -0.25, 1.0), axis=(0.0, 2.0, 0.0), radius=1.75)
    p4 = Cone(center=(-1.0, -0.75, -1.0), axis=(0.25, 0.25, 0.25), radius=0.5)
    n5 = Difference(p3, p4)
    p6 = Cylinder(center=(-0.75, -0.5, 0.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    n7 = Intersection(n5, p6)
    tree = Union(n2, n7)
    return tree


# case 337, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_337():
    p0 = Cylinder(center=(-0.25, 1.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(-0.75, -0.5, 0.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    n2 = Intersection(p0, p1)
    p3 = Cone(center=(1.0, -0.25, 1.0), axis=(0.0, 2.0, 0.0), radius=1.75)
    p4 = Cone(center=(-1.0, -0.75, -1.0), axis=(0.25, 0.25, 0.25), radius=0.5)
    n5 = Difference(p3, p4)
    p6 = Cylinder(center=(-0.75, -0.5, 0.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    n7 = Intersection(n5, p6)
    tree = Union(n2, n7)
    return tree


# case 338, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_338():
    p0 = Cylinder(center=(-0.25, 1.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(-0.75, -0.5, 0.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    n2 = Intersection(p0, p1)
    p3 = Cone(center=(1.0, -0.25, 1.0), axis=(0.0, 2.0, 0.0), radius=1.75)
    p4 = Cone(center=(-1.0, -0.75, -1.0), axis=(0.0, 0.25, 0.0), radius=0.5)
    n5 = Difference(p3, p4)
    p6 = Cylinder(center=(-0.75, -0.5, 0.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    n7 = Intersection(n5, p6)
    tree = Union(n2, n7)
    return tree


# case 339, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_339():
    p0 = Cylinder(center=(-0.25, 1.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(-0.75, -0.5, 0.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    n2 = Intersection(p0, p1)
    p3 = Cone(center=(1.0, -0.25, 1.0), axis=(0.0, 2.0, 0.0), radius=1.75)
    p4 = Cone(center=(-1.0, -0.75, -1.0), axis=(0.0, 0.25, 0.0), radius=0.5)
    n5 = Difference(p3, p4)
    p6 = Cylinder(center=(-0.75, -0.5, 0.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    n7 = Union(n5, p6)
    tree = Union(n2, n7)
    return tree


# case 340, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_340():
    p0 = Cylinder(center=(-0.25, 1.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(-0.75, -0.5, 0.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    n2 = Intersection(p0, p1)
    p3 = Cone(center=(1.0, -0.25, 1.0), axis=(0.0, 2.0, 0.0), radius=1.75)
    p4 = Cone(center=(-1.0, -0.75, -1.0), axis=(0.0, 0.25, 0.0), radius=0.5)
    n5 = Difference(p3, p4)
    p6 = Cone(center=(-0.75, -0.5, 0.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    n7 = Union(n5, p6)
    tree = Union(n2, n7)
    return tree


# case 341, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_341():
    p0 = Cylinder(center=(-0.25, 1.0, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(-0.75, -0.5, 0.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    n2 = Intersection(p0, p1)
    p3 = Cone(center=(1.0, -0.25, 1.0), axis=(0.0, 2.0, 0.0), radius=1.75)
    p4 = Cone(center=(-1.0, -0.75, -1.0), axis=(0.0, 0.25, 0.0), radius=0.5)
    n5 = Difference(p3, p4)
    p6 = Cone(center=(-0.75, -0.5, 0.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    n7 = Union(n5, p6)
    tree = Union(n2, n7)
    return tree


# case 342, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 8.18133058): error -8.181e+00, tessellation -1.828e-01, bound 1.828e-01 -> wrong
# area      0 (true 21.6353524): error -2.164e+01, tessellation -2.392e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.534e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_342():
    p0 = Sphere(center=(-0.75, -0.25, -0.5), radius=1.25)
    p1 = Box(center=(-0.75, 1.0, 0.5), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 343, pyvista: wrong topology
# volume    7.99854887 (true 8.18128516): error -1.827e-01, tessellation -1.828e-01, bound 1.828e-01 -> tessellation
# area      20.5504781 (true 20.7551095): error -2.046e-01, tessellation -2.047e-01 -> tessellation
# hausdorff mesh->true 1.492e-02, true->mesh 1.496e-02, tessellation 1.540e-02 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_343():
    p0 = Sphere(center=(-0.75, -0.25, -0.5), radius=1.25)
    p1 = Box(center=(-0.75, 0.5, 0.5), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 345, trimesh-manifold: wrong volume
# volume    7.99847674 (true 8.18123087): error -1.828e-01, tessellation -1.828e-01, bound 1.828e-01 -> wrong
# area      19.3957388 (true 19.6349541): error -2.392e-01, tessellation -2.392e-01 -> tessellation
# hausdorff mesh->true 1.588e-02, true->mesh 1.625e-02, tessellation 1.625e-02 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume
# case 345, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 8.18123087): error -8.181e+00, tessellation -1.828e-01, bound 1.828e-01 -> wrong
# area      0 (true 19.6349541): error -1.963e+01, tessellation -2.392e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.625e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_345():
    p0 = Sphere(center=(-0.75, 0.5, 0.5), radius=1.25)
    p1 = Box(center=(-0.75, 0.5, 0.5), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 346, trimesh-manifold: wrong volume
# volume    7.99847674 (true 8.18123087): error -1.828e-01, tessellation -1.828e-01, bound 1.828e-01 -> wrong
# area      19.3957388 (true 19.6349541): error -2.392e-01, tessellation -2.392e-01 -> tessellation
# hausdorff mesh->true 1.596e-02, true->mesh 1.545e-02, tessellation 1.545e-02 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume
# case 346, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 8.18123087): error -8.181e+00, tessellation -1.828e-01, bound 1.828e-01 -> wrong
# area      0 (true 19.6349541): error -1.963e+01, tessellation -2.392e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.545e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_346():
    p0 = Sphere(center=(-0.75, 0.5, 0.5), radius=1.25)
    p1 = Box(center=(-0.75, 0.0, 0.5), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 347, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000100016594 (true 0.0001): error +1.659e-08, tessellation -7.345e-18, bound 2.204e-17 -> wrong
# area      2.00040007 (true 2.0004): error +6.638e-08, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_347():
    p0 = Box(center=(-0.75, 0.0, 0.5), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.75, 0.0, 0.5), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 348, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000200033188 (true 0.0002): error +3.319e-08, tessellation -2.204e-17, bound 2.204e-17 -> wrong
# area      4.00080013 (true 4.0008): error +1.328e-07, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
# case 348, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0002): error -2.000e-04, tessellation -2.204e-17, bound 2.204e-17 -> wrong
# area      0 (true 4.0008): error -4.001e+00, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 5.509e-18 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_348():
    p0 = Box(center=(0.5, 0.0, 0.5), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.75, 0.0, 0.5), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 349, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.54212569): error -1.542e+00, tessellation -4.040e-02, bound 1.096e-01 -> wrong
# area      0 (true 12.3370055): error -1.234e+01, tessellation -8.459e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 5.492e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 1) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_349():
    p0 = Torus(center=(0.75, -1.0, 0.75), axis=(0.0, 0.0, 1.0), major=1.25, minor=0.25)
    p1 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    p2 = Truncus(center=(1.0, -0.75, -0.75), axis=(1.75, 1.75, 1.75), r1=1.25, r2=0.5)
    n3 = Difference(p1, p2)
    p4 = Sphere(center=(0.25, 0.75, 0.75), radius=0.5)
    n5 = Intersection(n3, p4)
    tree = Difference(p0, n5)
    return tree


# case 350, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.54212569): error -1.542e+00, tessellation -4.040e-02, bound 1.096e-01 -> wrong
# area      0 (true 12.3370055): error -1.234e+01, tessellation -8.459e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 5.500e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 1) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_350():
    p0 = Torus(center=(0.75, -1.0, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.25, minor=0.25)
    p1 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    p2 = Truncus(center=(1.0, -0.75, -0.75), axis=(1.75, 1.75, 1.75), r1=1.25, r2=0.5)
    n3 = Difference(p1, p2)
    p4 = Sphere(center=(0.25, 0.75, 0.75), radius=0.5)
    n5 = Intersection(n3, p4)
    tree = Difference(p0, n5)
    return tree


# case 351, pyvista: crashed (exit code -11)
def case_351():
    p0 = Torus(center=(0.75, -1.0, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.25, minor=0.25)
    p1 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    p2 = Sphere(center=(0.25, 0.75, 0.75), radius=0.5)
    n3 = Difference(p1, p2)
    p4 = Sphere(center=(0.25, 0.75, 0.75), radius=0.5)
    n5 = Intersection(n3, p4)
    tree = Difference(p0, n5)
    return tree


# case 353, trimesh-manifold: wrong area
# volume    0.139780031 (true 0.142966571): error -3.187e-03, tessellation -3.187e-03, bound 3.531e-02 -> tessellation
# area      2.00157838 (true 1.85759983): error +1.440e-01, tessellation +4.649e-02 -> wrong
# hausdorff mesh->true 6.533e-03, true->mesh 6.484e-03, tessellation 6.529e-03 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 2, genus 0) -> not comparable
# verdict   WRONG: area
def case_353():
    p0 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    p1 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    p2 = Sphere(center=(0.25, 0.75, 0.75), radius=0.5)
    n3 = Difference(p1, p2)
    p4 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    n5 = Intersection(n3, p4)
    tree = Difference(p0, n5)
    return tree


# case 354, pyvista: crashed (exit code -11)
def case_354():
    p0 = Cylinder(center=(0.5, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    p1 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    p2 = Sphere(center=(0.25, 0.75, 0.75), radius=0.5)
    n3 = Difference(p1, p2)
    p4 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    n5 = Intersection(n3, p4)
    tree = Difference(p0, n5)
    return tree


# case 357, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_357():
    p0 = Box(center=(-1.0, 0.0, -1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.5, -1.0, 0.25), size=(1.0, 1.0, 0.0001))
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(0.0, 1.0, 0.0), axis=(0.0, 0.0, 0.25), radius=0.25)
    n4 = Intersection(n2, p3)
    p5 = Cylinder(center=(1.0, 0.25, 0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    p6 = Cone(center=(0.0, 0.0, 0.0), axis=(0.0, 0.0, 0.25), radius=1.0)
    n7 = Intersection(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 358, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_358():
    p0 = Box(center=(-1.0, 0.0, -1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.5, 0.0, 0.25), size=(1.0, 1.0, 0.0001))
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(0.0, 1.0, 0.0), axis=(0.0, 0.0, 0.25), radius=0.25)
    n4 = Intersection(n2, p3)
    p5 = Cylinder(center=(1.0, 0.25, 0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    p6 = Cone(center=(0.0, 0.0, 0.0), axis=(0.0, 0.0, 0.25), radius=1.0)
    n7 = Intersection(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 359, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_359():
    p0 = Box(center=(-1.0, 0.0, -1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.5, 0.0, 0.25), size=(1.0, 1.0, 0.0001))
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(0.0, 1.0, 0.0), axis=(0.0, 0.0, 0.25), radius=0.25)
    n4 = Intersection(n2, p3)
    p5 = Cylinder(center=(1.0, 0.25, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p6 = Cone(center=(0.0, 0.0, 0.0), axis=(0.0, 0.0, 0.25), radius=1.0)
    n7 = Intersection(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 360, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_360():
    p0 = Box(center=(-1.0, 0.0, -1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.0, 1.0, 0.0), size=(1.0, 1.0, 0.0001))
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(0.0, 1.0, 0.0), axis=(0.0, 0.0, 0.25), radius=0.25)
    n4 = Intersection(n2, p3)
    p5 = Cylinder(center=(1.0, 0.25, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p6 = Cone(center=(0.0, 0.0, 0.0), axis=(0.0, 0.0, 0.25), radius=1.0)
    n7 = Intersection(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 361, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_361():
    p0 = Cylinder(center=(-0.25, -0.25, -0.25), axis=(0.25, 0.25, 0.25), radius=2.0)
    p1 = Cone(center=(-1.0, -0.75, -0.25), axis=(1.25, 0.0, 0.0), radius=0.75)
    p2 = Box(center=(1.0, 1.0, -0.75), size=(2.0, 0.75, 1.25))
    p3 = Box(center=(-0.75, -0.75, 0.25), size=(1.0, 1.0, 0.0001))
    n4 = Intersection(p2, p3)
    n5 = Intersection(p1, n4)
    tree = Union(p0, n5)
    return tree


# case 362, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_362():
    p0 = Cone(center=(-0.25, -0.25, -0.25), axis=(0.25, 0.25, 0.25), radius=2.0)
    p1 = Cone(center=(-1.0, -0.75, -0.25), axis=(1.25, 0.0, 0.0), radius=0.75)
    p2 = Box(center=(1.0, 1.0, -0.75), size=(2.0, 0.75, 1.25))
    p3 = Box(center=(-0.75, -0.75, 0.25), size=(1.0, 1.0, 0.0001))
    n4 = Intersection(p2, p3)
    n5 = Intersection(p1, n4)
    tree = Union(p0, n5)
    return tree


# case 368, pyvista: wrong topology
# volume    21.978061 (true 22.0741891): error -9.613e-02, tessellation -1.437e-01, bound 1.560e-01 -> tessellation
# area      46.5588494 (true 46.5772987): error -1.845e-02, tessellation -1.621e-01 -> tessellation
# hausdorff mesh->true 8.373e-03, true->mesh 8.307e-03, tessellation 8.373e-03 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_368():
    p0 = Truncus(center=(-1.0, 0.25, 0.0), axis=(1.5, 1.5, 1.5), r1=1.75, r2=1.5)
    p1 = Cylinder(center=(0.75, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    n2 = Difference(p0, p1)
    p3 = Ellipsoid(center=(0.25, -0.25, -1.0), radii=(0.75, 1.0, 0.25))
    tree = Union(n2, p3)
    return tree


# case 369, pyvista: wrong topology
# volume    21.6162608 (true 21.7481997): error -1.319e-01, tessellation -1.406e-01, bound 1.560e-01 -> tessellation
# area      44.534048 (true 44.6510541): error -1.170e-01, tessellation -1.583e-01 -> tessellation
# hausdorff mesh->true 8.382e-03, true->mesh 8.367e-03, tessellation 8.367e-03 -> tessellation
# topology  1 components, genus 1, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_369():
    p0 = Truncus(center=(-1.0, 0.25, -1.0), axis=(1.5, 1.5, 1.5), r1=1.75, r2=1.5)
    p1 = Cylinder(center=(0.75, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    n2 = Difference(p0, p1)
    p3 = Ellipsoid(center=(0.25, -0.25, -1.0), radii=(0.75, 1.0, 0.25))
    tree = Union(n2, p3)
    return tree


# case 375, pyvista: wrong area, hausdorff, topology
# volume    0.401602923 (true 0.409562128): error -7.959e-03, tessellation -6.946e-03, bound 7.692e-01 -> tessellation
# area      4.39806907 (true 4.39522613): error +2.843e-03, tessellation -2.759e-04 -> wrong
# hausdorff mesh->true 8.387e-02, true->mesh 1.949e-02, tessellation 1.949e-02 -> wrong
# topology  2 components, genus 1, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_375():
    p0 = Torus(center=(0.5, 1.0, 0.0), axis=(0.0, 0.0, 1.0), major=1.0, minor=0.2)
    p1 = Sphere(center=(0.75, -0.75, 0.25), radius=2.0)
    tree = Difference(p0, p1)
    return tree


# case 377, pyvista: wrong topology
# volume    0.375150046 (true 0.380724004): error -5.574e-03, tessellation -5.574e-03, bound 4.137e-02 -> tessellation
# area      7.84154789 (true 7.89568416): error -5.414e-02, tessellation -5.414e-02 -> tessellation
# hausdorff mesh->true 4.467e-03, true->mesh 4.467e-03, tessellation 4.467e-03 -> tessellation
# topology  7 components, genus 9, watertight False, winding consistent False (true: 2, genus 0) -> wrong
# verdict   WRONG: topology
def case_377():
    p0 = Torus(center=(0.5, 0.75, 0.0), axis=(0.0, 0.0, 1.0), major=1.0, minor=0.2)
    p1 = Torus(center=(0.5, 1.0, 0.0), axis=(0.0, 0.0, 1.0), major=1.0, minor=0.2)
    tree = Difference(p0, p1)
    return tree


# case 379, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_379():
    p0 = Cylinder(center=(-0.25, 0.5, 0.5), axis=(1.0, 1.0, 1.0), radius=0.001)
    p1 = Truncus(center=(0.0, 0.25, 0.25), axis=(0.25, 0.25, 0.25), r1=2.0, r2=1.5)
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(1.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), major=1.75, minor=0.6124999999999999)
    n4 = Intersection(n2, p3)
    p5 = Torus(center=(0.5, 0.25, -0.5), axis=(0.0, 1.0, 0.0), major=1.0, minor=0.5)
    n6 = Difference(n4, p5)
    p7 = Cone(center=(1.0, -0.25, 0.5), axis=(0.0, 0.0, 0.75), radius=0.25)
    tree = Union(n6, p7)
    return tree


# case 380, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_380():
    p0 = Cylinder(center=(-0.25, 0.5, 0.5), axis=(1.0, 1.0, 1.0), radius=0.001)
    p1 = Truncus(center=(0.0, 0.25, 0.25), axis=(0.25, 0.25, 0.25), r1=2.0, r2=1.5)
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(1.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), major=1.75, minor=0.6124999999999999)
    n4 = Intersection(n2, p3)
    p5 = Torus(center=(0.5, 0.25, -0.5), axis=(0.0, 1.0, 0.0), major=1.0, minor=0.35)
    n6 = Difference(n4, p5)
    p7 = Cone(center=(1.0, -0.25, 0.5), axis=(0.0, 0.0, 0.75), radius=0.25)
    tree = Union(n6, p7)
    return tree


# case 381, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_381():
    p0 = Cylinder(center=(-0.25, 0.5, 0.5), axis=(1.0, 1.0, 1.0), radius=0.001)
    p1 = Truncus(center=(0.0, 0.25, 0.25), axis=(0.25, 0.25, 0.25), r1=2.0, r2=1.5)
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(1.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), major=1.75, minor=0.6124999999999999)
    n4 = Intersection(n2, p3)
    p5 = Torus(center=(1.0, -0.25, -0.75), axis=(0.0, 1.0, 0.0), major=1.0, minor=0.35)
    n6 = Difference(n4, p5)
    p7 = Cone(center=(1.0, -0.25, 0.5), axis=(0.0, 0.0, 0.75), radius=0.25)
    tree = Union(n6, p7)
    return tree


# case 382, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_382():
    p0 = Cylinder(center=(-0.25, 0.5, 0.5), axis=(1.0, 1.0, 1.0), radius=0.001)
    p1 = Truncus(center=(0.0, 0.25, 0.25), axis=(0.25, 0.25, 0.25), r1=2.0, r2=1.5)
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(1.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), major=1.75, minor=0.6124999999999999)
    n4 = Intersection(n2, p3)
    p5 = Torus(center=(1.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), major=1.75, minor=0.6124999999999999)
    n6 = Difference(n4, p5)
    p7 = Cone(center=(1.0, -0.25, 0.5), axis=(0.0, 0.0, 0.75), radius=0.25)
    tree = Union(n6, p7)
    return tree


# case 383, trimesh-manifold: wrong area, topology
# volume    0.0487725808 (true 0.0490873852): error -3.148e-04, tessellation -3.148e-04, bound 7.315e-01 -> tessellation
# area      1.03671094 (true 0.817261307): error +2.194e-01, tessellation +7.433e-02 -> wrong
# hausdorff mesh->true 1.391e-02, true->mesh 1.095e-03, tessellation 1.179e-02 -> tessellation
# topology  26 components, genus 7, watertight False, winding consistent False (true: 33, genus 0, from mesh) -> wrong
# verdict   WRONG: area, topology
# case 383, pyvista: crashed (exit code -11)
def case_383():
    p0 = Cylinder(center=(-0.25, 0.5, 0.5), axis=(1.0, 1.0, 1.0), radius=0.001)
    p1 = Truncus(center=(0.0, 0.25, 0.25), axis=(0.25, 0.25, 0.25), r1=2.0, r2=1.5)
    n2 = Union(p0, p1)
    p3 = Torus(center=(1.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), major=1.75, minor=0.6124999999999999)
    n4 = Intersection(n2, p3)
    p5 = Torus(center=(1.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), major=1.75, minor=0.6124999999999999)
    n6 = Difference(n4, p5)
    p7 = Cone(center=(1.0, -0.25, 0.5), axis=(0.0, 0.0, 0.75), radius=0.25)
    tree = Union(n6, p7)
    return tree


# case 384, trimesh-manifold: wrong area, topology
# volume    0.0487725808 (true 0.0490873852): error -3.148e-04, tessellation -3.148e-04, bound 7.315e-01 -> tessellation
# area      1.02889702 (true 0.817261307): error +2.116e-01, tessellation +7.433e-02 -> wrong
# hausdorff mesh->true 1.391e-02, true->mesh 1.121e-03, tessellation 1.179e-02 -> tessellation
# topology  23 components, genus 4.5, watertight False, winding consistent False (true: 33, genus 0, from mesh) -> wrong
# verdict   WRONG: area, topology
# case 384, pyvista: crashed (exit code -11)
def case_384():
    p0 = Cylinder(center=(-0.25, 0.75, 0.5), axis=(1.0, 1.0, 1.0), radius=0.001)
    p1 = Truncus(center=(0.0, 0.25, 0.25), axis=(0.25, 0.25, 0.25), r1=2.0, r2=1.5)
    n2 = Union(p0, p1)
    p3 = Torus(center=(1.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), major=1.75, minor=0.6124999999999999)
    n4 = Intersection(n2, p3)
    p5 = Torus(center=(1.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), major=1.75, minor=0.6124999999999999)
    n6 = Difference(n4, p5)
    p7 = Cone(center=(1.0, -0.25, 0.5), axis=(0.0, 0.0, 0.75), radius=0.25)
    tree = Union(n6, p7)
    return tree


# case 385, trimesh-manifold: wrong topology
# volume    3.71892598 (true 3.73275327): error -1.383e-02, tessellation -1.383e-02, bound 7.315e-01 -> tessellation
# area      25.6767079 (true 25.7636868): error -8.698e-02, tessellation -8.698e-02 -> tessellation
# hausdorff mesh->true 1.458e-02, true->mesh 1.229e-02, tessellation 1.427e-02 -> tessellation
# topology  62 components, genus 34, watertight False, winding consistent False (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
# case 385, pyvista: crashed (exit code -11)
def case_385():
    p0 = Cylinder(center=(-0.25, 0.75, 0.5), axis=(1.0, 1.0, 1.0), radius=0.001)
    p1 = Truncus(center=(0.0, 0.25, 0.25), axis=(0.25, 0.25, 0.25), r1=2.0, r2=1.5)
    n2 = Union(p0, p1)
    p3 = Torus(center=(1.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), major=1.75, minor=0.6124999999999999)
    n4 = Difference(n2, p3)
    p5 = Torus(center=(1.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), major=1.75, minor=0.6124999999999999)
    n6 = Difference(n4, p5)
    p7 = Cone(center=(1.0, -0.25, 0.5), axis=(0.0, 0.0, 0.75), radius=0.25)
    tree = Union(n6, p7)
    return tree


# case 386, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_386():
    p0 = Cylinder(center=(-0.75, -1.0, -0.75), axis=(1.0, 0.0, 0.0), radius=0.001)
    p1 = Box(center=(-0.1767766952966368, 0.8838834764831844, 0.25), size=(1.75, 2.0, 0.25), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(0.25, 0.0, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p4 = Sphere(center=(0.75, -0.75, 0.75), radius=2.0)
    p5 = Ellipsoid(center=(0.5, 0.5, 0.25), radii=(1.0, 1.0, 1.25))
    n6 = Union(p4, p5)
    n7 = Difference(p3, n6)
    tree = Intersection(n2, n7)
    return tree


# case 387, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_387():
    p0 = Cylinder(center=(0.25, 0.0, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p1 = Box(center=(-0.1767766952966368, 0.8838834764831844, 0.25), size=(1.75, 2.0, 0.25), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(0.25, 0.0, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p4 = Sphere(center=(0.75, -0.75, 0.75), radius=2.0)
    p5 = Ellipsoid(center=(0.5, 0.5, 0.25), radii=(1.0, 1.0, 1.25))
    n6 = Union(p4, p5)
    n7 = Difference(p3, n6)
    tree = Intersection(n2, n7)
    return tree


# case 388, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_388():
    p0 = Cylinder(center=(0.25, 0.0, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p1 = Box(center=(-0.1767766952966368, 0.8838834764831844, 0.25), size=(1.75, 0.25, 0.25), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(0.25, 0.0, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p4 = Sphere(center=(0.75, -0.75, 0.75), radius=2.0)
    p5 = Ellipsoid(center=(0.5, 0.5, 0.25), radii=(1.0, 1.0, 1.25))
    n6 = Union(p4, p5)
    n7 = Difference(p3, n6)
    tree = Intersection(n2, n7)
    return tree


# case 389, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_389():
    p0 = Cylinder(center=(0.25, 0.0, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p1 = Box(center=(-0.1767766952966368, 0.8838834764831844, 0.25), size=(1.75, 0.25, 0.25), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(0.25, 0.0, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p4 = Sphere(center=(0.75, -0.75, 0.75), radius=2.0)
    p5 = Ellipsoid(center=(0.5, 0.5, 0.25), radii=(0.25, 0.25, 0.25))
    n6 = Union(p4, p5)
    n7 = Difference(p3, n6)
    tree = Intersection(n2, n7)
    return tree


# case 390, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_390():
    p0 = Cylinder(center=(0.25, 0.0, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p1 = Box(center=(-0.1767766952966368, 0.8838834764831844, 0.25), size=(1.75, 0.25, 0.25), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(0.25, 0.0, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p4 = Sphere(center=(0.75, -0.75, 0.75), radius=2.0)
    p5 = Ellipsoid(center=(0.5, 0.75, 0.25), radii=(0.25, 0.25, 0.25))
    n6 = Union(p4, p5)
    n7 = Difference(p3, n6)
    tree = Intersection(n2, n7)
    return tree


# case 391, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_391():
    p0 = Cylinder(center=(0.25, 0.0, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p1 = Box(center=(-0.1767766952966368, 0.8838834764831844, 0.25), size=(1.75, 0.25, 0.25), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(0.25, 0.0, 0.25), axis=(0.0, 0.0, 1.0), radius=0.001)
    p4 = Sphere(center=(0.75, -0.75, 0.75), radius=2.0)
    p5 = Ellipsoid(center=(0.5, 0.75, 0.25), radii=(0.25, 0.25, 0.25))
    n6 = Union(p4, p5)
    n7 = Difference(p3, n6)
    tree = Difference(n2, n7)
    return tree


# case 394, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000100016594 (true 0.0001): error +1.659e-08, tessellation -6.939e-18, bound 3.305e-17 -> wrong
# area      2.00040007 (true 2.0004): error +6.638e-08, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_394():
    p0 = Box(center=(-0.25, 0.5, 0.75), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.25, 1.0, 0.5), size=(1.0, 1.0, 0.0001))
    n2 = Difference(p0, p1)
    p3 = Box(center=(-0.25, 0.5, 0.75), size=(1.0, 1.0, 0.0001))
    tree = Intersection(n2, p3)
    return tree


# case 395, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_395():
    p0 = Box(center=(-0.25, 1.0, 0.5), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.25, 1.0, 0.5), size=(1.0, 1.0, 0.0001))
    n2 = Difference(p0, p1)
    p3 = Box(center=(-0.25, 0.5, 0.75), size=(1.0, 1.0, 0.0001))
    tree = Intersection(n2, p3)
    return tree


# case 397, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000100016594 (true 0.0001): error +1.659e-08, tessellation -1.102e-17, bound 3.305e-17 -> wrong
# area      2.00040007 (true 2.0004): error +6.638e-08, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_397():
    p0 = Box(center=(-0.25, 1.0, 0.5), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.25, 1.0, -0.25), size=(1.0, 1.0, 0.0001))
    n2 = Difference(p0, p1)
    p3 = Box(center=(-0.25, 0.5, 0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(n2, p3)
    return tree


# case 398, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000100016594 (true 0.0001): error +1.659e-08, tessellation -1.102e-17, bound 3.305e-17 -> wrong
# area      2.00040007 (true 2.0004): error +6.638e-08, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_398():
    p0 = Box(center=(-0.25, 1.0, 0.5), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.25, 0.5, 0.75), size=(1.0, 1.0, 0.0001))
    n2 = Difference(p0, p1)
    p3 = Box(center=(-0.25, 0.5, 0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(n2, p3)
    return tree


# case 399, trimesh-manifold: wrong area, hausdorff
# volume    0.500099995 (true 0.5001): error -4.885e-09, tessellation +1.110e-16, bound 1.220e-16 -> exact
# area      6.00039998 (true 6.0004): error -1.558e-08, tessellation -8.882e-16 -> wrong
# hausdorff mesh->true 3.810e-08, true->mesh 3.813e-08, tessellation 2.776e-16 -> wrong
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: area, hausdorff
# case 399, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.5001): error -5.001e-01, tessellation +1.110e-16, bound 1.220e-16 -> wrong
# area      0 (true 6.0004): error -6.000e+00, tessellation -8.882e-16 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.776e-16 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_399():
    p0 = Box(center=(0.17677669529663698, 1.2374368670764582, 0.25), size=(1.0, 0.5, 1.0), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.5, -0.75, 0.25), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 400, pyvista: wrong topology
# volume    0.0976402853 (true 0.0982698865): error -6.296e-04, tessellation -6.296e-04, bound 6.296e-04 -> tessellation
# area      2.97932895 (true 2.98208314): error -2.754e-03, tessellation -2.520e-03 -> tessellation
# hausdorff mesh->true 1.204e-03, true->mesh 1.204e-03, tessellation 1.204e-03 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_400():
    p0 = Box(center=(1.0, 0.75, 0.25), size=(1.0, 1.0, 0.0001))
    p1 = Truncus(center=(0.5, 1.0, 0.5), axis=(0.0, 0.0, 0.5), r1=0.25, r2=0.25)
    tree = Union(p0, p1)
    return tree


# case 402, pyvista: wrong area, hausdorff, topology
# volume    0.227605378 (true 0.229074449): error -1.469e-03, tessellation -1.469e-03, bound 2.099e-03 -> tessellation
# area      1.78454964 (true 2.29890028): error -5.144e-01, tessellation -9.675e-03 -> wrong
# hausdorff mesh->true 2.131e-03, true->mesh 2.280e-01, tessellation 2.151e-03 -> wrong
# topology  2 components, genus 3.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_402():
    p0 = Truncus(center=(0.5, 1.0, 0.5), axis=(0.0, 0.0, 0.5), r1=0.25, r2=0.25)
    p1 = Truncus(center=(0.5, 1.0, 0.5), axis=(0.0, 0.0, 0.5), r1=0.25, r2=0.5)
    tree = Union(p0, p1)
    return tree


# case 403, pyvista: wrong area, hausdorff, topology
# volume    0.300764248 (true 0.302705527): error -1.941e-03, tessellation -1.941e-03, bound 2.938e-03 -> tessellation
# area      2.7133567 (true 3.10747437): error -3.941e-01, tessellation -1.402e-02 -> wrong
# hausdorff mesh->true 2.135e-03, true->mesh 2.277e-01, tessellation 2.144e-03 -> wrong
# topology  1 components, genus 2, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_403():
    p0 = Truncus(center=(0.5, 1.0, 0.5), axis=(0.0, 0.0, 0.5), r1=0.5, r2=0.25)
    p1 = Truncus(center=(0.5, 1.0, 0.5), axis=(0.0, 0.0, 0.5), r1=0.25, r2=0.5)
    tree = Union(p0, p1)
    return tree


# case 411, pyvista: crashed (exit code -11)
def case_411():
    p0 = Cylinder(center=(0.25, 0.25, 0.5), axis=(1.75, 0.0, 0.0), radius=0.5)
    p1 = Sphere(center=(0.75, 0.25, 0.5), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.25, 0.25, 0.5), axis=(1.75, 0.0, 0.0), radius=0.5)
    p4 = Cylinder(center=(0.25, 0.25, 0.5), axis=(0.075, -0.125, 0.25), radius=1.5)
    n5 = Intersection(p3, p4)
    tree = Intersection(n2, n5)
    return tree


# case 412, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.91450802): error -1.915e+00, tessellation -1.228e-02, bound 1.228e-02 -> wrong
# area      0 (true 13.5258205): error -1.353e+01, tessellation -5.988e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 4.990e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_412():
    p0 = Truncus(center=(0.5, -1.0, 1.0), axis=(0.0, 0.75, 0.0), r1=0.5, r2=1.25)
    p1 = Box(center=(0.25, -0.25, 0.25), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 413, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.0157249569 (true 0.015725): error -4.309e-08, tessellation +9.714e-17, bound 1.092e-16 -> wrong
# area      2.37539983 (true 2.3754): error -1.733e-07, tessellation +8.882e-16 -> wrong
# hausdorff mesh->true 5.131e-08, true->mesh 5.131e-08, tessellation 1.241e-16 -> wrong
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
# case 413, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.015725): error -1.572e-02, tessellation +9.714e-17, bound 1.092e-16 -> wrong
# area      0 (true 2.3754): error -2.375e+00, tessellation +8.882e-16 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.241e-16 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_413():
    p0 = Box(center=(0.5, -1.0, 1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.39951905283832906, 0.8080127018922193, 0.0), size=(0.25, 0.25, 0.25), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Union(p0, p1)
    return tree


# case 414, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.0157249569 (true 0.015725): error -4.309e-08, tessellation +9.714e-17, bound 1.046e-16 -> wrong
# area      2.37539983 (true 2.3754): error -1.733e-07, tessellation +8.882e-16 -> wrong
# hausdorff mesh->true 5.131e-08, true->mesh 5.131e-08, tessellation 1.241e-16 -> wrong
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
# case 414, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.015725): error -1.572e-02, tessellation +9.714e-17, bound 1.046e-16 -> wrong
# area      0 (true 2.3754): error -2.375e+00, tessellation +8.882e-16 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.241e-16 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_414():
    p0 = Box(center=(0.5, 0.25, 1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.39951905283832906, 0.8080127018922193, 0.0), size=(0.25, 0.25, 0.25), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Union(p0, p1)
    return tree


# case 415, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.125099942 (true 0.1251): error -5.804e-08, tessellation +8.327e-17, bound 1.463e-16 -> wrong
# area      3.75039971 (true 3.7504): error -2.935e-07, tessellation +4.441e-16 -> wrong
# hausdorff mesh->true 5.131e-08, true->mesh 5.131e-08, tessellation 1.249e-16 -> wrong
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
# case 415, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.1251): error -1.251e-01, tessellation +8.327e-17, bound 1.463e-16 -> wrong
# area      0 (true 3.7504): error -3.750e+00, tessellation +4.441e-16 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.249e-16 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_415():
    p0 = Box(center=(0.5, 0.25, 1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.39951905283832906, 0.8080127018922193, 0.0), size=(0.5, 0.25, 1.0), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Union(p0, p1)
    return tree


# case 416, trimesh-manifold: wrong volume, area, hausdorff
# volume    9.99569893e-05 (true 0.0001): error -4.301e-08, tessellation +6.666e-17, bound 2.093e-16 -> wrong
# area      2.00039983 (true 2.0004): error -1.720e-07, tessellation +8.882e-16 -> wrong
# hausdorff mesh->true 5.131e-08, true->mesh 5.131e-08, tessellation 1.055e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_416():
    p0 = Box(center=(0.5, 0.25, 1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.5, 0.25, 1.0), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 417, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000124946237 (true 0.000125): error -5.376e-08, tessellation +8.332e-17, bound 2.139e-16 -> wrong
# area      2.50044981 (true 2.50045): error -1.935e-07, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 5.131e-08, true->mesh 5.131e-08, tessellation 1.055e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
# case 417, pyvista: wrong volume, area, hausdorff, topology
# volume    2.49892473e-05 (true 0.000125): error -1.000e-04, tessellation +8.332e-17, bound 2.139e-16 -> wrong
# area      0.375237398 (true 2.50045): error -2.125e+00, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 5.131e-08, true->mesh 3.742e-01, tessellation 1.055e-16 -> wrong
# topology  4 components, genus 3.5, watertight False, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_417():
    p0 = Box(center=(0.5, 0.25, 1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.5, 0.5, 1.0), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 418, trimesh-manifold: wrong volume, area, hausdorff
# volume    9.99569893e-05 (true 0.0001): error -4.301e-08, tessellation +6.666e-17, bound 2.185e-16 -> wrong
# area      2.00039983 (true 2.0004): error -1.720e-07, tessellation +8.882e-16 -> wrong
# hausdorff mesh->true 5.131e-08, true->mesh 5.131e-08, tessellation 1.055e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_418():
    p0 = Box(center=(0.5, 0.5, 1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.5, 0.5, 1.0), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 424, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 8.3321411): error -8.332e+00, tessellation -5.344e-02, bound 5.344e-02 -> wrong
# area      0 (true 28.7647058): error -2.876e+01, tessellation -1.387e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 8.427e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_424():
    p0 = Cylinder(center=(-0.25, 0.25, 0.5), axis=(0.5, 0.5, 0.5), radius=1.75)
    p1 = Cylinder(center=(0.5, 0.25, 0.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(0.5, 0.25, 0.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    tree = Union(n2, p3)
    return tree


# case 426, pyvista: wrong area, hausdorff, topology
# volume    4.93594769 (true 4.94100111): error -5.053e-03, tessellation -8.676e-03, bound 3.295e-02 -> tessellation
# area      30.165169 (true 29.8149414): error +3.502e-01, tessellation -9.560e-02 -> wrong
# hausdorff mesh->true 3.460e-02, true->mesh 5.568e-03, tessellation 5.568e-03 -> wrong
# topology  6 components, genus 4.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_426():
    p0 = Box(center=(1.0, 0.25, 0.75), size=(1.5, 1.25, 1.75))
    p1 = Truncus(center=(0.5, -0.5, 1.0), axis=(0.0, 0.5, 0.0), r1=0.25, r2=1.75)
    n2 = Union(p0, p1)
    p3 = Cone(center=(0.25, -1.0, -0.75), axis=(2.0, 0.0, 0.0), radius=1.25)
    tree = Difference(n2, p3)
    return tree


# case 427, pyvista: wrong area, topology
# volume    2.64947064 (true 2.6554536): error -5.983e-03, tessellation -9.605e-03, bound 3.295e-02 -> tessellation
# area      24.1082544 (true 23.8586356): error +2.496e-01, tessellation -1.013e-01 -> wrong
# hausdorff mesh->true 1.124e-02, true->mesh 7.540e-03, tessellation 7.540e-03 -> tessellation
# topology  6 components, genus 4, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, topology
def case_427():
    p0 = Box(center=(1.0, 0.25, 0.75), size=(1.5, 1.25, 0.5))
    p1 = Truncus(center=(0.5, -0.5, 1.0), axis=(0.0, 0.5, 0.0), r1=0.25, r2=1.75)
    n2 = Union(p0, p1)
    p3 = Cone(center=(0.25, -1.0, -0.75), axis=(2.0, 0.0, 0.0), radius=1.25)
    tree = Difference(n2, p3)
    return tree


# case 428, pyvista: wrong volume, area, topology
# volume    5.98570009 (true 5.92793884): error +5.776e-02, tessellation -3.059e-02, bound 3.295e-02 -> wrong
# area      37.2730788 (true 37.0024372): error +2.706e-01, tessellation -1.480e-01 -> wrong
# hausdorff mesh->true 5.881e-03, true->mesh 7.765e-03, tessellation 7.765e-03 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, topology
def case_428():
    p0 = Box(center=(1.0, 0.25, 0.75), size=(1.5, 1.25, 0.5))
    p1 = Truncus(center=(0.5, -0.5, 1.0), axis=(0.0, 0.5, 0.0), r1=0.25, r2=1.75)
    n2 = Union(p0, p1)
    p3 = Cone(center=(0.25, -1.0, -0.75), axis=(2.0, 0.0, 0.0), radius=1.25)
    tree = Union(n2, p3)
    return tree


# case 429, pyvista: wrong volume, area, hausdorff, topology
# volume    6.00002991 (true 5.92793884): error +7.209e-02, tessellation -3.059e-02, bound 3.295e-02 -> wrong
# area      37.3129515 (true 37.0024372): error +3.105e-01, tessellation -1.480e-01 -> wrong
# hausdorff mesh->true 4.703e-02, true->mesh 5.439e-03, tessellation 5.439e-03 -> wrong
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_429():
    p0 = Box(center=(0.0, 0.25, 0.75), size=(1.5, 1.25, 0.5))
    p1 = Truncus(center=(0.5, -0.5, 1.0), axis=(0.0, 0.5, 0.0), r1=0.25, r2=1.75)
    n2 = Union(p0, p1)
    p3 = Cone(center=(0.25, -1.0, -0.75), axis=(2.0, 0.0, 0.0), radius=1.25)
    tree = Union(n2, p3)
    return tree


# case 430, pyvista: wrong volume, hausdorff, topology
# volume    5.67637868 (true 5.83394107): error -1.576e-01, tessellation -3.105e-02, bound 3.295e-02 -> wrong
# area      36.7424197 (true 36.6624512): error +7.997e-02, tessellation -1.500e-01 -> tessellation
# hausdorff mesh->true 1.019e-01, true->mesh 6.301e-02, tessellation 7.126e-03 -> wrong
# topology  1 components, genus 2, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, hausdorff, topology
def case_430():
    p0 = Box(center=(0.0, 0.25, 0.75), size=(1.5, 1.25, 0.5))
    p1 = Truncus(center=(0.5, -0.5, 1.0), axis=(0.5, 0.0, 0.0), r1=0.25, r2=1.75)
    n2 = Union(p0, p1)
    p3 = Cone(center=(0.25, -1.0, -0.75), axis=(2.0, 0.0, 0.0), radius=1.25)
    tree = Union(n2, p3)
    return tree


# case 431, pyvista: crashed (exit code -11)
def case_431():
    p0 = Cone(center=(0.25, -1.0, -0.75), axis=(2.0, 0.0, 0.0), radius=1.25)
    p1 = Truncus(center=(0.5, -0.5, 1.0), axis=(0.5, 0.0, 0.0), r1=0.25, r2=1.75)
    n2 = Union(p0, p1)
    p3 = Cone(center=(0.25, -1.0, -0.75), axis=(2.0, 0.0, 0.0), radius=1.25)
    tree = Union(n2, p3)
    return tree


# case 432, pyvista: crashed (exit code -11)
def case_432():
    p0 = Cone(center=(0.25, -1.0, -0.75), axis=(2.0, 0.0, 0.0), radius=1.25)
    p1 = Truncus(center=(0.5, -0.5, 1.0), axis=(0.5, 0.0, 0.0), r1=0.25, r2=1.25)
    n2 = Union(p0, p1)
    p3 = Cone(center=(0.25, -1.0, -0.75), axis=(2.0, 0.0, 0.0), radius=1.25)
    tree = Union(n2, p3)
    return tree


# case 433, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.0342474831): error -3.425e-02, tessellation -3.678e-03, bound 3.158e-01 -> tessellation
# area      0 (true 2.77738666): error -2.777e+00, tessellation -5.293e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.167e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_433():
    p0 = Box(center=(-0.75, -0.5, 1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.019797410448706282, 0.7903214931529607, 0.5), size=(0.25, 1.75, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p2 = Sphere(center=(-0.75, -0.75, -0.75), radius=1.5)
    n3 = Intersection(p1, p2)
    tree = Union(p0, n3)
    return tree


# case 434, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.0342474831): error -3.425e-02, tessellation -3.678e-03, bound 3.158e-01 -> tessellation
# area      0 (true 2.77738666): error -2.777e+00, tessellation -5.293e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.078e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_434():
    p0 = Box(center=(-0.75, -0.75, -0.75), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.019797410448706282, 0.7903214931529607, 0.5), size=(0.25, 1.75, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p2 = Sphere(center=(-0.75, -0.75, -0.75), radius=1.5)
    n3 = Intersection(p1, p2)
    tree = Union(p0, n3)
    return tree


# case 440, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_440():
    p0 = Cylinder(center=(-0.25, -0.5, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Sphere(center=(0.75, -0.5, 0.0), radius=0.5)
    p2 = Cylinder(center=(0.25, 0.5, 0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    n3 = Intersection(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Box(center=(0.0, 0.5, 1.0), size=(1.0, 1.0, 0.0001))
    p6 = Cylinder(center=(-1.0, 0.75, -0.5), axis=(1.0, 0.0, 0.0), radius=0.001)
    n7 = Difference(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 441, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_441():
    p0 = Cylinder(center=(-0.25, -0.5, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Sphere(center=(0.75, -0.5, 0.0), radius=0.5)
    p2 = Cylinder(center=(0.25, 0.5, 0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    n3 = Intersection(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Box(center=(0.0, 0.5, 1.0), size=(1.0, 1.0, 0.0001))
    p6 = Cylinder(center=(0.25, 0.5, 0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    n7 = Difference(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 442, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_442():
    p0 = Cylinder(center=(0.25, -0.5, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Sphere(center=(0.75, -0.5, 0.0), radius=0.5)
    p2 = Cylinder(center=(0.25, 0.5, 0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    n3 = Intersection(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Box(center=(0.0, 0.5, 1.0), size=(1.0, 1.0, 0.0001))
    p6 = Cylinder(center=(0.25, 0.5, 0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    n7 = Difference(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 443, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_443():
    p0 = Cylinder(center=(0.25, -0.5, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Sphere(center=(0.75, -0.5, 0.0), radius=0.5)
    p2 = Sphere(center=(0.25, 0.5, 0.25), radius=0.5)
    n3 = Intersection(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Box(center=(0.0, 0.5, 1.0), size=(1.0, 1.0, 0.0001))
    p6 = Cylinder(center=(0.25, 0.5, 0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    n7 = Difference(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 444, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_444():
    p0 = Cylinder(center=(0.25, -0.5, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Sphere(center=(0.75, -0.5, 0.0), radius=0.25)
    p2 = Sphere(center=(0.25, 0.5, 0.25), radius=0.5)
    n3 = Intersection(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Box(center=(0.0, 0.5, 1.0), size=(1.0, 1.0, 0.0001))
    p6 = Cylinder(center=(0.25, 0.5, 0.25), axis=(1.0, 0.0, 0.0), radius=0.001)
    n7 = Difference(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 452, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_452():
    p0 = Cylinder(center=(0.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), radius=1.5)
    p1 = Torus(center=(-0.75, 1.0, 0.25), axis=(0.25916052767440806, -0.4319342127906801, 0.8638684255813602), major=0.5, minor=0.25)
    p2 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    n3 = Intersection(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Cylinder(center=(1.0, 1.0, -1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    p6 = Ellipsoid(center=(-1.0, 0.75, -0.75), radii=(0.25, 2.0, 1.25))
    n7 = Intersection(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 453, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_453():
    p0 = Cylinder(center=(0.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), radius=1.5)
    p1 = Torus(center=(-0.75, 1.0, 0.25), axis=(0.25916052767440806, -0.4319342127906801, 0.8638684255813602), major=0.5, minor=0.25)
    p2 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    n3 = Intersection(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Cylinder(center=(1.0, 1.0, -1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    p6 = Ellipsoid(center=(-0.75, -0.25, -1.0), radii=(0.25, 2.0, 1.25))
    n7 = Intersection(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 454, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_454():
    p0 = Cylinder(center=(0.0, -0.25, -0.75), axis=(0.0, 0.0, 1.0), radius=1.5)
    p1 = Torus(center=(-0.75, 1.0, 0.25), axis=(0.25916052767440806, -0.4319342127906801, 0.8638684255813602), major=0.5, minor=0.25)
    p2 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    n3 = Intersection(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Cylinder(center=(1.0, 1.0, -1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    p6 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    n7 = Intersection(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 455, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_455():
    p0 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    p1 = Torus(center=(-0.75, 1.0, 0.25), axis=(0.25916052767440806, -0.4319342127906801, 0.8638684255813602), major=0.5, minor=0.25)
    p2 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    n3 = Intersection(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Cylinder(center=(1.0, 1.0, -1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    p6 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    n7 = Intersection(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 456, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_456():
    p0 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    p1 = Torus(center=(-0.75, 1.0, 0.25), axis=(0.25916052767440806, -0.4319342127906801, 0.8638684255813602), major=0.5, minor=0.25)
    p2 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=2.0)
    n3 = Intersection(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Cylinder(center=(1.0, 1.0, -1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    p6 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    n7 = Intersection(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 457, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_457():
    p0 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    p1 = Torus(center=(-0.75, 1.0, 0.25), axis=(0.25916052767440806, -0.4319342127906801, 0.8638684255813602), major=0.5, minor=0.25)
    p2 = Cylinder(center=(-1.0, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=2.0)
    n3 = Intersection(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Cylinder(center=(1.0, 1.0, -1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    p6 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    n7 = Intersection(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 458, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_458():
    p0 = Cylinder(center=(1.0, 1.0, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    p1 = Torus(center=(-0.75, 1.0, 0.25), axis=(0.25916052767440806, -0.4319342127906801, 0.8638684255813602), major=0.5, minor=0.25)
    p2 = Cylinder(center=(-1.0, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=2.0)
    n3 = Intersection(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Cylinder(center=(1.0, 1.0, -1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    p6 = Cylinder(center=(-0.75, -0.25, -1.0), axis=(0.6, -1.0, 2.0), radius=0.5)
    n7 = Intersection(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 459, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_459():
    p0 = Cone(center=(0.25, 0.0, -0.5), axis=(0.0, 0.5, 0.0), radius=0.5)
    p1 = Box(center=(0.25, 0.0, -1.0), size=(1.0, 1.0, 0.0001))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(-0.75, -0.25, 1.0), axis=(1.0, 1.0, 1.0), radius=0.001)
    n4 = Intersection(n2, p3)
    p5 = Box(center=(0.5915063509461096, -0.524519052838329, 1.0), size=(2.0, 0.75, 1.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 460, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_460():
    p0 = Box(center=(0.5915063509461096, -0.524519052838329, 1.0), size=(2.0, 0.75, 1.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.25, 0.0, -1.0), size=(1.0, 1.0, 0.0001))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(-0.75, -0.25, 1.0), axis=(1.0, 1.0, 1.0), radius=0.001)
    n4 = Intersection(n2, p3)
    p5 = Box(center=(0.5915063509461096, -0.524519052838329, 1.0), size=(2.0, 0.75, 1.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 461, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_461():
    p0 = Box(center=(0.5915063509461096, -0.524519052838329, 1.0), size=(2.0, 0.75, 1.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.25, 0.0, -1.0), size=(1.0, 1.0, 0.0001))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(0.25, 0.0, -1.0), axis=(1.0, 1.0, 1.0), radius=0.001)
    n4 = Intersection(n2, p3)
    p5 = Box(center=(0.5915063509461096, -0.524519052838329, 1.0), size=(2.0, 0.75, 1.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 462, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_462():
    p0 = Box(center=(0.5915063509461096, -0.524519052838329, 1.0), size=(2.0, 0.75, 1.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.25, 0.0, 1.0), size=(1.0, 1.0, 0.0001))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(0.25, 0.0, -1.0), axis=(1.0, 1.0, 1.0), radius=0.001)
    n4 = Intersection(n2, p3)
    p5 = Box(center=(0.5915063509461096, -0.524519052838329, 1.0), size=(2.0, 0.75, 1.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 463, trimesh-manifold: wrong area, hausdorff
# volume    0.0156250005 (true 0.015625): error +5.338e-10, tessellation -3.469e-18, bound 5.057e-06 -> tessellation
# area      0.375000009 (true 0.375): error +8.541e-09, tessellation -3.331e-16 -> wrong
# hausdorff mesh->true 1.542e-08, true->mesh 1.514e-08, tessellation 2.289e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: area, hausdorff
def case_463():
    p0 = Box(center=(0.5915063509461096, -0.524519052838329, 1.0), size=(2.0, 0.75, 1.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Cylinder(center=(0.25, 0.0, 1.0), axis=(0.0, 0.0, 1.0), radius=0.001)
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.29237170472273677, -0.9563047559630354, 0.75), size=(0.25, 0.25, 0.25), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n4 = Intersection(n2, p3)
    p5 = Cylinder(center=(0.75, 0.0, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(n4, p5)
    return tree


# case 464, trimesh-manifold: wrong area, hausdorff
# volume    0.00781250027 (true 0.0078125): error +2.669e-10, tessellation +6.418e-17, bound 5.057e-06 -> tessellation
# area      0.250000006 (true 0.25): error +6.406e-09, tessellation +1.110e-16 -> wrong
# hausdorff mesh->true 1.542e-08, true->mesh 1.519e-08, tessellation 2.289e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: area, hausdorff
def case_464():
    p0 = Box(center=(0.5915063509461096, -0.524519052838329, 1.0), size=(2.0, 0.75, 1.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Cylinder(center=(0.25, 0.0, 1.0), axis=(0.0, 0.0, 1.0), radius=0.001)
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.29237170472273677, -0.9563047559630354, 0.25), size=(0.25, 0.25, 0.25), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n4 = Intersection(n2, p3)
    p5 = Cylinder(center=(0.75, 0.0, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(n4, p5)
    return tree


# case 472, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_472():
    p0 = Sphere(center=(-0.75, 0.75, 0.0), radius=0.5)
    p1 = Ellipsoid(center=(0.0, -0.5, 0.0), radii=(2.0, 1.25, 1.25))
    n2 = Intersection(p0, p1)
    p3 = Box(center=(0.6441356407915924, 0.45835496753281146, -0.5), size=(1.5, 2.0, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.75, 0.5, -0.75), axis=(0.0, 0.0, 0.25), radius=1.75)
    p6 = Cylinder(center=(-0.75, -0.75, 0.75), axis=(0.0, 1.0, 0.0), radius=0.001)
    n7 = Intersection(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 473, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_473():
    p0 = Sphere(center=(-0.75, 0.75, 0.0), radius=0.5)
    p1 = Ellipsoid(center=(0.0, -0.5, 0.0), radii=(2.0, 1.25, 1.25))
    n2 = Intersection(p0, p1)
    p3 = Box(center=(0.8634144193336449, -0.25887359943946514, -0.5), size=(1.5, 2.0, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.75, 0.5, -0.75), axis=(0.0, 0.0, 0.25), radius=1.75)
    p6 = Cylinder(center=(-0.75, -0.75, 0.75), axis=(0.0, 1.0, 0.0), radius=0.001)
    n7 = Intersection(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 474, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_474():
    p0 = Sphere(center=(-0.75, 0.75, 0.0), radius=0.5)
    p1 = Ellipsoid(center=(0.0, -0.5, 0.0), radii=(2.0, 1.25, 1.25))
    n2 = Intersection(p0, p1)
    p3 = Box(center=(0.8634144193336449, -0.25887359943946514, -0.5), size=(1.5, 2.0, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.75, 0.5, -0.75), axis=(0.0, 0.0, 0.25), radius=1.75)
    p6 = Cylinder(center=(-0.75, -0.75, 0.75), axis=(0.0, 0.0, 1.0), radius=0.001)
    n7 = Intersection(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 475, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_475():
    p0 = Box(center=(0.8634144193336449, -0.25887359943946514, -0.5), size=(1.5, 2.0, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Ellipsoid(center=(0.0, -0.5, 0.0), radii=(2.0, 1.25, 1.25))
    n2 = Intersection(p0, p1)
    p3 = Box(center=(0.8634144193336449, -0.25887359943946514, -0.5), size=(1.5, 2.0, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.75, 0.5, -0.75), axis=(0.0, 0.0, 0.25), radius=1.75)
    p6 = Cylinder(center=(-0.75, -0.75, 0.75), axis=(0.0, 0.0, 1.0), radius=0.001)
    n7 = Intersection(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 476, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_476():
    p0 = Box(center=(0.8634144193336449, -0.25887359943946514, -0.5), size=(1.5, 2.0, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Ellipsoid(center=(0.0, -0.5, 0.0), radii=(2.0, 1.25, 1.25))
    n2 = Intersection(p0, p1)
    p3 = Box(center=(0.8634144193336449, -0.25887359943946514, -0.5), size=(1.5, 2.0, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.75, 0.5, -0.75), axis=(0.0, 0.0, 0.25), radius=1.75)
    p6 = Cylinder(center=(-0.75, -0.75, -0.5), axis=(0.0, 0.0, 1.0), radius=0.001)
    n7 = Intersection(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 477, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_477():
    p0 = Box(center=(0.0, 0.0, 0.0), size=(1.5, 2.0, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Ellipsoid(center=(0.0, -0.5, 0.0), radii=(2.0, 1.25, 1.25))
    n2 = Intersection(p0, p1)
    p3 = Box(center=(0.8634144193336449, -0.25887359943946514, -0.5), size=(1.5, 2.0, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.75, 0.5, -0.75), axis=(0.0, 0.0, 0.25), radius=1.75)
    p6 = Cylinder(center=(-0.75, -0.75, -0.5), axis=(0.0, 0.0, 1.0), radius=0.001)
    n7 = Intersection(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 478, trimesh-manifold: wrong area, topology
# volume    2.5959024 (true 2.61660128): error -2.070e-02, tessellation -2.070e-02, bound 6.002e-01 -> tessellation
# area      14.2993469 (true 14.205968): error +9.338e-02, tessellation +3.748e-02 -> wrong
# hausdorff mesh->true 1.372e-02, true->mesh 1.338e-02, tessellation 1.357e-02 -> tessellation
# topology  4 components, genus 1.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: area, topology
# case 478, pyvista: crashed (exit code -11)
def case_478():
    p0 = Box(center=(0.0, 0.0, 0.0), size=(1.5, 2.0, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Ellipsoid(center=(0.0, -0.5, 0.0), radii=(2.0, 1.25, 1.25))
    n2 = Intersection(p0, p1)
    p3 = Box(center=(0.8634144193336449, -0.25887359943946514, -0.5), size=(1.5, 2.0, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.75, 0.5, -0.75), axis=(0.0, 0.0, 0.25), radius=1.75)
    p6 = Ellipsoid(center=(0.0, -0.5, 0.0), radii=(2.0, 1.25, 1.25))
    n7 = Intersection(p5, p6)
    tree = Difference(n4, n7)
    return tree


# case 479, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_479():
    p0 = Box(center=(-0.7903214931529607, 0.019797410448706282, 0.5), size=(0.75, 0.5, 1.25), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(-0.25, 0.25, 0.75), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(0.25, -0.75, -0.25), axis=(0.0, 1.0, 0.0), major=2.25, minor=0.7875)
    p4 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    p5 = Cylinder(center=(0.0, 0.0, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n6 = Union(p4, p5)
    n7 = Intersection(p3, n6)
    tree = Union(n2, n7)
    return tree


# case 480, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_480():
    p0 = Box(center=(-0.7903214931529607, 0.019797410448706282, 0.5), size=(0.75, 0.5, 1.25), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(0.25, -0.75, -0.25), axis=(0.0, 1.0, 0.0), major=2.25, minor=0.7875)
    p4 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    p5 = Cylinder(center=(0.0, 0.0, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n6 = Union(p4, p5)
    n7 = Intersection(p3, n6)
    tree = Union(n2, n7)
    return tree


# case 481, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_481():
    p0 = Box(center=(-0.7903214931529607, 0.019797410448706282, 0.5), size=(0.75, 0.5, 1.25), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(0.25, -0.75, -0.25), axis=(0.0, 1.0, 0.0), major=2.25, minor=0.7875)
    p4 = Box(center=(0.25, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    p5 = Cylinder(center=(0.0, 0.0, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n6 = Union(p4, p5)
    n7 = Intersection(p3, n6)
    tree = Union(n2, n7)
    return tree


# case 482, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_482():
    p0 = Box(center=(0.5710427146109082, 0.6974311565235702, 0.0), size=(0.75, 0.5, 1.25), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(0.25, -0.75, -0.25), axis=(0.0, 1.0, 0.0), major=2.25, minor=0.7875)
    p4 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    p5 = Cylinder(center=(0.0, 0.0, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n6 = Union(p4, p5)
    n7 = Intersection(p3, n6)
    tree = Union(n2, n7)
    return tree


# case 483, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_483():
    p0 = Box(center=(0.5710427146109082, 0.6974311565235702, 0.0), size=(0.75, 0.5, 0.25), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(0.25, -0.75, -0.25), axis=(0.0, 1.0, 0.0), major=2.25, minor=0.7875)
    p4 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    p5 = Cylinder(center=(0.0, 0.0, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n6 = Union(p4, p5)
    n7 = Intersection(p3, n6)
    tree = Union(n2, n7)
    return tree


# case 484, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_484():
    p0 = Box(center=(0.5710427146109082, 0.6974311565235702, 0.0), size=(0.75, 0.5, 0.25), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(0.25, -0.75, 0.5), axis=(0.0, 1.0, 0.0), major=2.25, minor=0.7875)
    p4 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    p5 = Cylinder(center=(0.0, 0.0, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n6 = Union(p4, p5)
    n7 = Intersection(p3, n6)
    tree = Union(n2, n7)
    return tree


# case 485, trimesh-manifold: wrong area, hausdorff
# volume    0.000100016594 (true 0.0001): error +1.659e-08, tessellation +1.153e-16, bound 7.484e-01 -> tessellation
# area      2.00040007 (true 2.0004): error +6.638e-08, tessellation +6.661e-15 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> exact
# verdict   WRONG: area, hausdorff
def case_485():
    p0 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(0.25, -0.75, 0.5), axis=(0.0, 1.0, 0.0), major=2.25, minor=0.7875)
    p4 = Box(center=(-0.75, 0.25, -0.5), size=(1.0, 1.0, 0.0001))
    p5 = Cylinder(center=(0.0, 0.0, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n6 = Union(p4, p5)
    n7 = Intersection(p3, n6)
    tree = Union(n2, n7)
    return tree


# case 486, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_486():
    p0 = Cylinder(center=(1.0, 0.75, 1.0), axis=(0.5, 0.0, 0.0), radius=2.0)
    p1 = Cylinder(center=(0.5, 0.0, 0.5), axis=(0.3, -0.5, 1.0), radius=0.001)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-1.0, 0.0, -0.5), axis=(1.0, 0.0, 0.0), radius=0.001)
    n4 = Intersection(n2, p3)
    p5 = Ellipsoid(center=(1.0, -0.25, 0.75), radii=(1.0, 0.5, 1.75))
    p6 = Box(center=(-0.75, 0.25, 1.0), size=(1.75, 0.75, 1.75))
    n7 = Union(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 487, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_487():
    p0 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.5, 0.0, 0.0), radius=2.0)
    p1 = Cylinder(center=(0.5, 0.0, 0.5), axis=(0.3, -0.5, 1.0), radius=0.001)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-1.0, 0.0, -0.5), axis=(1.0, 0.0, 0.0), radius=0.001)
    n4 = Intersection(n2, p3)
    p5 = Ellipsoid(center=(1.0, -0.25, 0.75), radii=(1.0, 0.5, 1.75))
    p6 = Box(center=(-0.75, 0.25, 1.0), size=(1.75, 0.75, 1.75))
    n7 = Union(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 488, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_488():
    p0 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.15, -0.25, 0.5), radius=2.0)
    p1 = Cylinder(center=(0.5, 0.0, 0.5), axis=(0.3, -0.5, 1.0), radius=0.001)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-1.0, 0.0, -0.5), axis=(1.0, 0.0, 0.0), radius=0.001)
    n4 = Intersection(n2, p3)
    p5 = Ellipsoid(center=(1.0, -0.25, 0.75), radii=(1.0, 0.5, 1.75))
    p6 = Box(center=(-0.75, 0.25, 1.0), size=(1.75, 0.75, 1.75))
    n7 = Union(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 493, pyvista: wrong hausdorff, topology
# volume    5.69283834 (true 5.72812619): error -3.529e-02, tessellation -3.529e-02, bound 3.715e-02 -> tessellation
# area      18.9525582 (true 18.90972): error +4.284e-02, tessellation -4.707e-02 -> tessellation
# hausdorff mesh->true 4.791e-02, true->mesh 4.815e-03, tessellation 4.815e-03 -> wrong
# topology  1 components, genus 1, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: hausdorff, topology
def case_493():
    p0 = Truncus(center=(-0.5, -0.75, -0.5), axis=(1.75, 0.0, 0.0), r1=1.0, r2=1.0)
    p1 = Cylinder(center=(-0.25, 0.25, 0.0), axis=(0.0, 0.0, 1.5), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 494, pyvista: wrong topology
# volume    6.00859124 (true 6.04223149): error -3.364e-02, tessellation -3.770e-02, bound 3.977e-02 -> tessellation
# area      28.0488515 (true 28.1476872): error -9.884e-02, tessellation -1.102e-01 -> tessellation
# hausdorff mesh->true 4.815e-03, true->mesh 4.815e-03, tessellation 4.815e-03 -> tessellation
# topology  1 components, genus 1.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_494():
    p0 = Cylinder(center=(-0.5, -0.75, -0.5), axis=(1.75, 0.0, 0.0), radius=1.0)
    p1 = Truncus(center=(0.5, -0.25, 0.25), axis=(0.0, 0.0, 0.25), r1=1.5, r2=0.25)
    tree = Union(p0, p1)
    return tree


# case 496, pyvista: wrong area, hausdorff, topology
# volume    5.46252906 (true 5.49778714): error -3.526e-02, tessellation -3.526e-02, bound 4.030e-02 -> tessellation
# area      12.2289371 (true 17.2787596): error -5.050e+00, tessellation -5.795e-02 -> wrong
# hausdorff mesh->true 4.815e-03, true->mesh 1.677e-01, tessellation 4.815e-03 -> wrong
# topology  21 components, genus 26, watertight False, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_496():
    p0 = Cylinder(center=(-0.5, -0.75, -0.5), axis=(0.25, 0.0, 0.0), radius=1.0)
    p1 = Cylinder(center=(-0.5, -0.75, -0.5), axis=(1.75, 0.0, 0.0), radius=1.0)
    tree = Union(p0, p1)
    return tree


# case 497, pyvista: wrong area, hausdorff, topology
# volume    5.4625291 (true 5.49778714): error -3.526e-02, tessellation -3.526e-02, bound 5.541e-02 -> tessellation
# area      9.17290271 (true 17.2787596): error -8.106e+00, tessellation -5.795e-02 -> wrong
# hausdorff mesh->true 4.815e-03, true->mesh 4.994e-01, tessellation 4.815e-03 -> wrong
# topology  22 components, genus 28.5, watertight False, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_497():
    p0 = Cylinder(center=(-0.5, -0.75, -0.5), axis=(1.75, 0.0, 0.0), radius=1.0)
    p1 = Cylinder(center=(-0.5, -0.75, -0.5), axis=(1.0, 0.0, 0.0), radius=1.0)
    tree = Union(p0, p1)
    return tree


# case 498, pyvista: wrong hausdorff, topology
# volume    5.96865811 (true 5.99648203): error -2.782e-02, tessellation -3.703e-02, bound 5.541e-02 -> tessellation
# area      18.7361959 (true 18.7774609): error -4.127e-02, tessellation -6.039e-02 -> tessellation
# hausdorff mesh->true 3.201e-02, true->mesh 4.815e-03, tessellation 4.815e-03 -> wrong
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: hausdorff, topology
def case_498():
    p0 = Cylinder(center=(-0.5, -0.75, -0.75), axis=(1.75, 0.0, 0.0), radius=1.0)
    p1 = Cylinder(center=(-0.5, -0.75, -0.5), axis=(1.0, 0.0, 0.0), radius=1.0)
    tree = Union(p0, p1)
    return tree


# case 501, pyvista: wrong volume, area, hausdorff, topology
# volume    8.68122061 (true 8.86903751): error -1.878e-01, tessellation -1.772e-01, bound 1.846e-01 -> wrong
# area      24.8202902 (true 25.0496924): error -2.294e-01, tessellation -1.411e-01 -> wrong
# hausdorff mesh->true 1.576e-02, true->mesh 6.309e-02, tessellation 1.641e-02 -> wrong
# topology  1 components, genus 2.5, watertight False, winding consistent False (true: 1, genus 1) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_501():
    p0 = Cone(center=(-0.25, -0.25, -0.75), axis=(0.0, 0.0, 0.25), radius=0.5)
    p1 = Sphere(center=(-0.75, -1.0, -0.25), radius=1.25)
    n2 = Union(p0, p1)
    p3 = Box(center=(0.25, -0.25, 0.5), size=(1.0, 1.0, 0.0001))
    p4 = Box(center=(-0.24999999999999997, 0.43301270189221935, 0.0), size=(1.0, 0.75, 1.0), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    n5 = Union(p3, p4)
    p6 = Sphere(center=(0.0, 0.25, 0.0), radius=0.25)
    n7 = Union(n5, p6)
    tree = Union(n2, n7)
    return tree


# case 507, pyvista: wrong topology
# volume    6.97122911 (true 7.11756821): error -1.463e-01, tessellation -1.452e-01, bound 2.188e-01 -> tessellation
# area      19.994427 (true 20.1694846): error -1.751e-01, tessellation -1.829e-01 -> tessellation
# hausdorff mesh->true 1.457e-02, true->mesh 1.492e-02, tessellation 1.492e-02 -> tessellation
# topology  3 components, genus 2, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_507():
    p0 = Ellipsoid(center=(0.0, 1.0, -0.25), radii=(1.25, 1.25, 1.0))
    p1 = Cone(center=(0.0, 1.0, -0.25), axis=(2.0, 0.0, 0.0), radius=1.75)
    p2 = Cylinder(center=(0.25, 0.0, 0.75), axis=(0.0, 0.0, 1.0), radius=1.25)
    n3 = Intersection(p1, p2)
    tree = Union(p0, n3)
    return tree


# case 508, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 7.5612276): error -7.561e+00, tessellation -1.386e-01, bound 2.188e-01 -> wrong
# area      0 (true 22.1752268): error -2.218e+01, tessellation -1.618e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.474e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_508():
    p0 = Ellipsoid(center=(0.0, 1.0, -0.25), radii=(1.25, 1.25, 1.0))
    p1 = Cone(center=(0.0, 1.0, -0.25), axis=(0.0, 0.0, 2.0), radius=1.75)
    p2 = Cylinder(center=(0.25, 0.0, 0.75), axis=(0.0, 0.0, 1.0), radius=1.25)
    n3 = Intersection(p1, p2)
    tree = Union(p0, n3)
    return tree


# case 509, pyvista: crashed (exit code -11)
def case_509():
    p0 = Ellipsoid(center=(0.0, 1.0, -0.25), radii=(1.25, 1.25, 1.0))
    p1 = Cone(center=(0.0, 1.0, -0.25), axis=(0.0, 0.0, 2.0), radius=1.75)
    p2 = Cylinder(center=(0.25, 0.0, 0.75), axis=(0.0, 0.0, 1.0), radius=1.25)
    n3 = Union(p1, p2)
    tree = Union(p0, n3)
    return tree


# case 510, pyvista: wrong area, hausdorff, topology
# volume    13.0656293 (true 13.0021738): error +6.346e-02, tessellation -1.299e-01, bound 2.188e-01 -> tessellation
# area      34.4807363 (true 34.7768294): error -2.961e-01, tessellation -1.450e-01 -> wrong
# hausdorff mesh->true 4.734e-02, true->mesh 5.153e-02, tessellation 1.475e-02 -> wrong
# topology  7 components, genus 7, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_510():
    p0 = Ellipsoid(center=(0.0, 1.0, 1.0), radii=(1.25, 1.25, 1.0))
    p1 = Cone(center=(0.0, 1.0, -0.25), axis=(0.0, 0.0, 2.0), radius=1.75)
    p2 = Cylinder(center=(0.25, 0.0, 0.75), axis=(0.0, 0.0, 1.0), radius=1.25)
    n3 = Union(p1, p2)
    tree = Union(p0, n3)
    return tree


# case 511, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 11.2601116): error -1.126e+01, tessellation -1.232e-01, bound 2.188e-01 -> wrong
# area      0 (true 30.6643825): error -3.066e+01, tessellation -1.490e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.485e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_511():
    p0 = Ellipsoid(center=(0.0, 1.0, 1.0), radii=(1.25, 1.25, 1.0))
    p1 = Cone(center=(0.0, 1.0, -0.25), axis=(0.0, 0.0, 2.0), radius=1.75)
    p2 = Cylinder(center=(0.25, 1.0, 0.75), axis=(0.0, 0.0, 1.0), radius=1.25)
    n3 = Union(p1, p2)
    tree = Union(p0, n3)
    return tree


# case 512, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 10.0817927): error -1.008e+01, tessellation -6.431e-02, bound 9.780e-02 -> wrong
# area      0 (true 30.7967707): error -3.080e+01, tessellation -1.252e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 6.155e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_512():
    p0 = Cylinder(center=(0.0, 1.0, 1.0), axis=(0.0, 0.0, 1.25), radius=1.0)
    p1 = Cone(center=(0.0, 1.0, -0.25), axis=(0.0, 0.0, 2.0), radius=1.75)
    p2 = Cylinder(center=(0.25, 1.0, 0.75), axis=(0.0, 0.0, 1.0), radius=1.25)
    n3 = Union(p1, p2)
    tree = Union(p0, n3)
    return tree


# case 514, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0654498469): error -6.545e-02, tessellation -4.197e-04, bound 4.197e-04 -> wrong
# area      0 (true 1.6635): error -1.664e+00, tessellation -9.822e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.214e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_514():
    p0 = Cone(center=(0.25, -1.0, 0.5), axis=(0.25, 0.0, 0.0), radius=0.5)
    p1 = Box(center=(0.0, -0.25, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(p0, p1)
    return tree


# case 515, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0654498469): error -6.545e-02, tessellation -4.197e-04, bound 4.197e-04 -> wrong
# area      0 (true 1.6635): error -1.664e+00, tessellation -9.822e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.656e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_515():
    p0 = Cone(center=(0.25, -1.0, 0.5), axis=(0.25, 0.0, 0.0), radius=0.5)
    p1 = Box(center=(0.0, 0.0, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(p0, p1)
    return tree


# case 516, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0654498469): error -6.545e-02, tessellation -4.197e-04, bound 4.197e-04 -> wrong
# area      0 (true 1.6635): error -1.664e+00, tessellation -9.822e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.710e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_516():
    p0 = Cone(center=(0.5, -1.0, 0.5), axis=(0.25, 0.0, 0.0), radius=0.5)
    p1 = Box(center=(0.0, 0.0, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(p0, p1)
    return tree


# case 517, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.130899694): error -1.309e-01, tessellation -8.395e-04, bound 8.395e-04 -> wrong
# area      0 (true 1.8961189): error -1.896e+00, tessellation -9.487e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.929e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_517():
    p0 = Cone(center=(0.5, -1.0, 0.5), axis=(0.5, 0.0, 0.0), radius=0.5)
    p1 = Box(center=(0.0, 0.0, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(p0, p1)
    return tree


# case 518, trimesh-manifold: wrong volume
# volume    0.130035208 (true 0.130874694): error -8.395e-04, tessellation -8.395e-04, bound 8.395e-04 -> wrong
# area      2.38638026 (true 2.39587744): error -9.497e-03, tessellation -9.497e-03 -> tessellation
# hausdorff mesh->true 1.686e-03, true->mesh 1.682e-03, tessellation 1.682e-03 -> tessellation
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> exact
# verdict   WRONG: volume
# case 518, pyvista: crashed (exit code -11)
def case_518():
    p0 = Cone(center=(0.0, 0.0, -0.75), axis=(0.5, 0.0, 0.0), radius=0.5)
    p1 = Box(center=(0.0, 0.0, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(p0, p1)
    return tree


# case 519, trimesh-manifold: wrong volume
# volume    0.13004771 (true 0.130887194): error -8.395e-04, tessellation -8.395e-04, bound 8.395e-04 -> wrong
# area      2.13655609 (true 2.14604817): error -9.492e-03, tessellation -9.492e-03 -> tessellation
# hausdorff mesh->true 1.655e-03, true->mesh 2.091e-03, tessellation 2.091e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> exact
# verdict   WRONG: volume
# case 519, pyvista: wrong topology
# volume    0.130053842 (true 0.130887194): error -8.334e-04, tessellation -8.395e-04, bound 8.395e-04 -> tessellation
# area      2.13658061 (true 2.14604817): error -9.468e-03, tessellation -9.492e-03 -> tessellation
# hausdorff mesh->true 1.669e-03, true->mesh 2.091e-03, tessellation 2.091e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
def case_519():
    p0 = Cone(center=(0.0, 0.0, -0.75), axis=(0.5, 0.0, 0.0), radius=0.5)
    p1 = Box(center=(0.0, 0.5, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(p0, p1)
    return tree


# case 520, trimesh-manifold: wrong volume
# volume    0.0650238549 (true 0.0654435969): error -4.197e-04, tessellation -4.197e-04, bound 4.197e-04 -> wrong
# area      1.7785942 (true 1.78841909): error -9.825e-03, tessellation -9.825e-03 -> tessellation
# hausdorff mesh->true 1.040e-03, true->mesh 1.121e-03, tessellation 1.121e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> exact
# verdict   WRONG: volume
# case 520, pyvista: wrong volume
# volume    0.0650238554 (true 0.0654435969): error -4.197e-04, tessellation -4.197e-04, bound 4.197e-04 -> wrong
# area      1.7785942 (true 1.78841909): error -9.825e-03, tessellation -9.825e-03 -> tessellation
# hausdorff mesh->true 1.055e-03, true->mesh 1.121e-03, tessellation 1.121e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> exact
# verdict   WRONG: volume
def case_520():
    p0 = Cone(center=(0.0, 0.0, -0.75), axis=(0.25, 0.0, 0.0), radius=0.5)
    p1 = Box(center=(0.0, 0.5, -0.75), size=(1.0, 1.0, 0.0001))
    tree = Difference(p0, p1)
    return tree


# case 521, pyvista: crashed (exit code -11)
def case_521():
    p0 = Truncus(center=(-0.75, 0.25, 0.0), axis=(1.75, 1.75, 1.75), r1=1.75, r2=1.5)
    p1 = Cylinder(center=(1.0, -0.25, 0.25), axis=(1.0, 1.0, 1.0), radius=0.001)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-0.75, -0.75, -0.75), axis=(1.0, 0.0, 0.0), radius=0.001)
    tree = Union(n2, p3)
    return tree


# case 522, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 25.1948092): error -2.519e+01, tessellation -1.616e-01, bound 1.616e-01 -> wrong
# area      0 (true 47.7475658): error -4.775e+01, tessellation -1.577e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 8.361e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_522():
    p0 = Truncus(center=(-0.75, 0.25, 0.25), axis=(1.75, 1.75, 1.75), r1=1.75, r2=1.5)
    p1 = Cylinder(center=(1.0, -0.25, 0.25), axis=(1.0, 1.0, 1.0), radius=0.001)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-0.75, -0.75, -0.75), axis=(1.0, 0.0, 0.0), radius=0.001)
    tree = Union(n2, p3)
    return tree


# case 523, trimesh-manifold: wrong volume
# volume    25.0332286 (true 25.1948068): error -1.616e-01, tessellation -1.616e-01, bound 1.616e-01 -> wrong
# area      47.5848501 (true 47.7427494): error -1.579e-01, tessellation -1.579e-01 -> tessellation
# hausdorff mesh->true 8.306e-03, true->mesh 8.382e-03, tessellation 8.382e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> exact
# verdict   WRONG: volume
def case_523():
    p0 = Truncus(center=(-0.75, 0.25, 0.25), axis=(1.75, 1.75, 1.75), r1=1.75, r2=1.5)
    p1 = Cylinder(center=(-0.75, -0.25, 0.25), axis=(1.0, 1.0, 1.0), radius=0.001)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-0.75, -0.75, -0.75), axis=(1.0, 0.0, 0.0), radius=0.001)
    tree = Union(n2, p3)
    return tree


# case 524, pyvista: wrong topology
# volume    14.6805537 (true 14.7753005): error -9.475e-02, tessellation -9.476e-02, bound 9.476e-02 -> tessellation
# area      36.7619134 (true 36.9195693): error -1.577e-01, tessellation -1.578e-01 -> tessellation
# hausdorff mesh->true 8.623e-03, true->mesh 8.717e-03, tessellation 8.717e-03 -> tessellation
# topology  1 components, genus 4.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
def case_524():
    p0 = Truncus(center=(-0.5, 0.75, 1.0), axis=(1.75, 0.0, 0.0), r1=2.0, r2=1.25)
    p1 = Cylinder(center=(-0.25, 0.25, -0.75), axis=(1.0, 1.0, 1.0), radius=0.001)
    tree = Difference(p0, p1)
    return tree


# case 525, pyvista: wrong topology
# volume    25.4277146 (true 25.5915738): error -1.639e-01, tessellation -1.641e-01, bound 1.641e-01 -> tessellation
# area      49.1886285 (true 49.3595305): error -1.709e-01, tessellation -1.723e-01 -> tessellation
# hausdorff mesh->true 9.227e-03, true->mesh 9.073e-03, tessellation 9.159e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
def case_525():
    p0 = Truncus(center=(-0.5, 0.75, 1.0), axis=(1.75, 1.75, 1.75), r1=2.0, r2=1.25)
    p1 = Cylinder(center=(-0.25, 0.25, -0.75), axis=(1.0, 1.0, 1.0), radius=0.001)
    tree = Difference(p0, p1)
    return tree


# case 526, pyvista: wrong topology
# volume    25.4274508 (true 25.5915734): error -1.641e-01, tessellation -1.641e-01, bound 1.641e-01 -> tessellation
# area      49.1883667 (true 49.3604549): error -1.721e-01, tessellation -1.721e-01 -> tessellation
# hausdorff mesh->true 9.319e-03, true->mesh 9.256e-03, tessellation 9.256e-03 -> tessellation
# topology  1 components, genus 5, watertight False, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_526():
    p0 = Truncus(center=(0.5, 0.75, 1.0), axis=(1.75, 1.75, 1.75), r1=2.0, r2=1.25)
    p1 = Cylinder(center=(-0.25, 0.25, -0.75), axis=(1.0, 1.0, 1.0), radius=0.001)
    tree = Difference(p0, p1)
    return tree


# case 527, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 25.5915754): error -2.559e+01, tessellation -1.641e-01, bound 1.641e-01 -> wrong
# area      0 (true 49.3563739): error -4.936e+01, tessellation -1.721e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 9.361e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_527():
    p0 = Truncus(center=(0.5, -0.25, 1.0), axis=(1.75, 1.75, 1.75), r1=2.0, r2=1.25)
    p1 = Cylinder(center=(-0.25, 0.25, -0.75), axis=(1.0, 1.0, 1.0), radius=0.001)
    tree = Difference(p0, p1)
    return tree


# case 528, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 25.59157): error -2.559e+01, tessellation -1.641e-01, bound 1.641e-01 -> wrong
# area      0 (true 49.3672629): error -4.937e+01, tessellation -1.721e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 9.274e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_528():
    p0 = Truncus(center=(0.5, -0.25, 1.0), axis=(1.75, 1.75, 1.75), r1=2.0, r2=1.25)
    p1 = Cylinder(center=(0.5, -0.25, 1.0), axis=(1.0, 1.0, 1.0), radius=0.001)
    tree = Difference(p0, p1)
    return tree


# case 529, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 8.58299075e-06): error -8.583e-06, tessellation -5.504e-08, bound 5.504e-08 -> wrong
# area      0 (true 0.0171785479): error -1.718e-02, tessellation -2.764e-05 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 4.815e-06 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_529():
    p0 = Cylinder(center=(0.5, -0.25, 1.0), axis=(1.0, 1.0, 1.0), radius=0.001)
    p1 = Cylinder(center=(0.0, 0.0, 0.0), axis=(1.0, 0.0, 0.0), radius=0.001)
    tree = Union(p0, p1)
    return tree


# case 531, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.000785398163): error -7.854e-04, tessellation -5.037e-06, bound 1.007e-05 -> wrong
# area      0 (true 1.57393792): error -1.574e+00, tessellation -1.008e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.145e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_531():
    p0 = Cylinder(center=(-1.0, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(1.0, 0.25, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(p0, p1)
    return tree


# case 533, pyvista: wrong area, hausdorff, topology
# volume    0.000669381221 (true 0.000672070156): error -2.689e-06, tessellation -2.680e-06, bound 1.007e-05 -> tessellation
# area      1.57901784 (true 1.34728163): error +2.317e-01, tessellation -5.365e-03 -> wrong
# hausdorff mesh->true 4.014e-01, true->mesh 4.285e-02, tessellation 2.036e-03 -> wrong
# topology  5 components, genus 11.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_533():
    p0 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(1.0, 0.25, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(p0, p1)
    return tree


# case 535, pyvista: wrong area, hausdorff, topology
# volume    0.00047656899 (true 0.000478305266): error -1.736e-06, tessellation -1.730e-06, bound 1.007e-05 -> tessellation
# area      1.66567573 (true 0.959750232): error +7.059e-01, tessellation -3.463e-03 -> wrong
# hausdorff mesh->true 4.808e-01, true->mesh 5.259e-02, tessellation 2.387e-03 -> wrong
# topology  9 components, genus 23, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_535():
    p0 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(0.5, 1.0, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(p0, p1)
    return tree


# case 536, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.000785398163): error -7.854e-04, tessellation -5.037e-06, bound 1.007e-05 -> wrong
# area      0 (true 1.57393792): error -1.574e+00, tessellation -1.008e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.168e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_536():
    p0 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(1.0, 1.0, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(p0, p1)
    return tree


# case 537, pyvista: wrong topology
# volume    6.12499998 (true 6.125): error -2.044e-08, tessellation +1.738e-08, bound 3.606e-01 -> tessellation
# area      20.1250895 (true 20.125): error +8.950e-05, tessellation +8.958e-05 -> tessellation
# hausdorff mesh->true 1.019e-02, true->mesh 8.784e-08, tessellation 1.019e-02 -> tessellation
# topology  1 components, genus 1, watertight False, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
def case_537():
    p0 = Cylinder(center=(-1.0, 0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Torus(center=(1.0, 0.0, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.75, minor=0.6124999999999999)
    n2 = Difference(p0, p1)
    p3 = Box(center=(-0.25, 0.75, 0.5), size=(1.25, 1.75, 0.5))
    p4 = Cylinder(center=(0.0, 1.0, 0.25), axis=(0.0, 0.75, 0.0), radius=0.75)
    n5 = Difference(p3, p4)
    n6 = Intersection(n2, n5)
    p7 = Box(center=(-0.774519052838329, -0.1584936490538903, 0.75), size=(1.75, 2.0, 1.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    tree = Union(n6, p7)
    return tree


# case 538, pyvista: wrong area, hausdorff, topology
# volume    1.09449428 (true 1.09375): error +7.443e-04, tessellation +3.109e-15, bound 3.606e-01 -> tessellation
# area      7.2681945 (true 7.375): error -1.068e-01, tessellation +2.220e-14 -> wrong
# hausdorff mesh->true 0.000e+00, true->mesh 7.146e-02, tessellation 0.000e+00 -> wrong
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_538():
    p0 = Cylinder(center=(-1.0, 0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Torus(center=(1.0, 0.0, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.75, minor=0.6124999999999999)
    n2 = Difference(p0, p1)
    p3 = Box(center=(-0.25, 0.75, 0.5), size=(1.25, 1.75, 0.5))
    p4 = Cylinder(center=(0.0, 1.0, 0.25), axis=(0.0, 0.75, 0.0), radius=0.75)
    n5 = Difference(p3, p4)
    n6 = Intersection(n2, n5)
    p7 = Box(center=(-0.25, 0.75, 0.5), size=(1.25, 1.75, 0.5))
    tree = Union(n6, p7)
    return tree


# case 539, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.0938035762): error -9.380e-02, tessellation +2.964e-07, bound 3.606e-01 -> tessellation
# area      0 (true 1.58264862): error -1.583e+00, tessellation +8.745e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.019e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_539():
    p0 = Cylinder(center=(-1.0, 0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Torus(center=(1.0, 0.0, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.75, minor=0.6124999999999999)
    n2 = Difference(p0, p1)
    p3 = Box(center=(-0.25, 0.75, 0.5), size=(1.25, 1.75, 0.5))
    p4 = Cylinder(center=(0.0, 1.0, 0.25), axis=(0.0, 0.75, 0.0), radius=0.75)
    n5 = Difference(p3, p4)
    n6 = Intersection(n2, n5)
    p7 = Box(center=(-0.25, 0.75, 0.5), size=(0.25, 0.75, 0.5))
    tree = Union(n6, p7)
    return tree


# case 540, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.0938003603): error -9.380e-02, tessellation +3.512e-06, bound 3.669e-01 -> tessellation
# area      0 (true 1.58267591): error -1.583e+00, tessellation +8.718e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.019e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_540():
    p0 = Cylinder(center=(-1.0, 0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Torus(center=(1.0, 0.0, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.75, minor=0.6124999999999999)
    n2 = Difference(p0, p1)
    p3 = Box(center=(-0.25, 0.75, 0.5), size=(1.25, 1.75, 0.5))
    p4 = Cylinder(center=(0.0, 1.0, 0.25), axis=(0.75, 0.75, 0.75), radius=0.75)
    n5 = Difference(p3, p4)
    n6 = Intersection(n2, n5)
    p7 = Box(center=(-0.25, 0.75, 0.5), size=(0.25, 0.75, 0.5))
    tree = Union(n6, p7)
    return tree


# case 541, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.000560904952): error -5.609e-04, tessellation +2.247e-06, bound 3.669e-01 -> tessellation
# area      0 (true 1.22802182): error -1.228e+00, tessellation +8.867e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.206e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_541():
    p0 = Cylinder(center=(-1.0, 0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Torus(center=(1.0, 0.0, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.75, minor=0.6124999999999999)
    n2 = Difference(p0, p1)
    p3 = Box(center=(-0.25, 0.75, 0.5), size=(1.25, 1.75, 0.5))
    p4 = Cylinder(center=(0.0, 1.0, 0.25), axis=(0.75, 0.75, 0.75), radius=0.75)
    p5 = Cylinder(center=(0.75, 0.25, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n6 = Intersection(p4, p5)
    n7 = Union(p3, n6)
    tree = Difference(n2, n7)
    return tree


# case 547, pyvista: wrong hausdorff, topology
# volume    0.304777523 (true 0.321218044): error -1.644e-02, tessellation -1.667e-02, bound 1.521e-01 -> tessellation
# area      3.27622561 (true 3.3829984): error -1.068e-01, tessellation -1.084e-01 -> tessellation
# hausdorff mesh->true 2.197e-02, true->mesh 1.444e-02, tessellation 1.444e-02 -> wrong
# topology  2 components, genus 1, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: hausdorff, topology
def case_547():
    p0 = Sphere(center=(-0.5, 0.75, -0.25), radius=1.0)
    p1 = Ellipsoid(center=(0.25, -0.25, -0.25), radii=(0.25, 1.25, 2.0))
    tree = Intersection(p0, p1)
    return tree


# case 549, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.0654498469): error -6.545e-02, tessellation -1.462e-03, bound 9.503e-02 -> tessellation
# area      0 (true 0.785398163): error -7.854e-01, tessellation -9.569e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.226e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_549():
    p0 = Sphere(center=(0.25, -0.25, -0.25), radius=1.0)
    p1 = Ellipsoid(center=(0.25, -0.25, -0.25), radii=(0.25, 0.25, 0.25))
    tree = Intersection(p0, p1)
    return tree


# case 551, trimesh-manifold: wrong volume
# volume    1.62820552 (true 1.6399019): error -1.170e-02, tessellation -1.170e-02, bound 1.170e-02 -> wrong
# area      13.0790102 (true 13.1172851): error -3.827e-02, tessellation -3.827e-02 -> tessellation
# hausdorff mesh->true 6.206e-03, true->mesh 6.358e-03, tessellation 6.358e-03 -> tessellation
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> exact
# verdict   WRONG: volume
def case_551():
    p0 = Box(center=(1.3660254037844386, -0.36602540378443876, 1.0), size=(1.25, 1.0, 0.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(1.0, -0.5, 0.25), size=(1.0, 1.0, 0.0001))
    n2 = Union(p0, p1)
    p3 = Sphere(center=(0.0, -1.0, -0.25), radius=0.5)
    p4 = Box(center=(0.7071067811865476, 0.35355339059327373, 0.5), size=(0.25, 1.5, 0.5), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    n5 = Union(p3, p4)
    tree = Union(n2, n5)
    return tree


# case 556, trimesh-manifold: wrong volume
# volume    1.62137744 (true 1.63307378): error -1.170e-02, tessellation -1.170e-02, bound 1.170e-02 -> wrong
# area      13.0412179 (true 13.0794927): error -3.827e-02, tessellation -3.827e-02 -> tessellation
# hausdorff mesh->true 6.278e-03, true->mesh 6.045e-03, tessellation 6.520e-03 -> tessellation
# topology  3 components, genus 0, watertight True, winding consistent True (true: 3, genus 0) -> exact
# verdict   WRONG: volume
def case_556():
    p0 = Box(center=(1.3660254037844386, -0.36602540378443876, 1.0), size=(1.25, 1.0, 0.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.0, -0.5, 0.25), size=(1.0, 1.0, 0.0001))
    n2 = Union(p0, p1)
    p3 = Sphere(center=(1.0, -1.0, -0.5), radius=0.5)
    p4 = Box(center=(0.774519052838329, 0.1584936490538903, 0.5), size=(0.25, 1.5, 0.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    n5 = Union(p3, p4)
    tree = Union(n2, n5)
    return tree


# case 557, trimesh-manifold: wrong volume
# volume    1.62137744 (true 1.63307378): error -1.170e-02, tessellation -1.170e-02, bound 1.170e-02 -> wrong
# area      13.0412179 (true 13.0794927): error -3.827e-02, tessellation -3.827e-02 -> tessellation
# hausdorff mesh->true 6.037e-03, true->mesh 6.393e-03, tessellation 6.550e-03 -> tessellation
# topology  3 components, genus 0, watertight True, winding consistent True (true: 3, genus 0) -> exact
# verdict   WRONG: volume
def case_557():
    p0 = Box(center=(1.3660254037844386, -0.36602540378443876, 1.0), size=(1.25, 1.0, 0.75), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    p1 = Box(center=(0.0, -0.5, 0.25), size=(1.0, 1.0, 0.0001))
    n2 = Union(p0, p1)
    p3 = Sphere(center=(1.0, 0.5, -0.5), radius=0.5)
    p4 = Box(center=(0.774519052838329, 0.1584936490538903, 0.5), size=(0.25, 1.5, 0.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    n5 = Union(p3, p4)
    tree = Union(n2, n5)
    return tree


# case 558, pyvista: wrong volume, topology
# volume    0.763837882 (true 0.786101058): error -2.226e-02, tessellation -5.042e-03, bound 5.042e-03 -> wrong
# area      8.4709469 (true 8.47230069): error -1.354e-03, tessellation -4.599e-02 -> tessellation
# hausdorff mesh->true 2.864e-03, true->mesh 2.977e-03, tessellation 2.977e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, topology
def case_558():
    p0 = Cone(center=(0.5, 0.25, 0.5), axis=(0.75, 0.0, 0.0), radius=1.0)
    p1 = Cylinder(center=(1.0, -0.5, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 559, pyvista: wrong topology
# volume    0.781173352 (true 0.786044225): error -4.871e-03, tessellation -5.040e-03, bound 5.042e-03 -> tessellation
# area      8.32539082 (true 8.36442256): error -3.903e-02, tessellation -4.705e-02 -> tessellation
# hausdorff mesh->true 2.842e-03, true->mesh 3.409e-03, tessellation 3.409e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_559():
    p0 = Cone(center=(0.5, 0.25, 0.5), axis=(0.75, 0.0, 0.0), radius=1.0)
    p1 = Cylinder(center=(1.0, -0.5, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 560, pyvista: wrong topology
# volume    0.781764176 (true 0.785660015): error -3.896e-03, tessellation -5.041e-03, bound 5.042e-03 -> tessellation
# area      7.54815175 (true 7.59271239): error -4.456e-02, tessellation -4.587e-02 -> tessellation
# hausdorff mesh->true 2.866e-03, true->mesh 4.168e-03, tessellation 4.168e-03 -> tessellation
# topology  1 components, genus 2, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_560():
    p0 = Cone(center=(0.5, 0.25, 0.5), axis=(0.75, 0.0, 0.0), radius=1.0)
    p1 = Cylinder(center=(0.5, 0.25, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 561, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.197134939): error -1.971e-01, tessellation -1.264e-03, bound 1.264e-03 -> wrong
# area      0 (true 3.93013241): error -3.930e+00, tessellation -2.141e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.408e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_561():
    p0 = Cylinder(center=(0.5, 0.25, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(0.75, 1.0, 0.0), axis=(0.25, 0.0, 0.0), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 562, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.196887735): error -1.969e-01, tessellation -1.264e-03, bound 1.264e-03 -> wrong
# area      0 (true 3.43295087): error -3.433e+00, tessellation -1.989e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.408e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_562():
    p0 = Cylinder(center=(0.5, 0.25, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(0.5, 0.25, 0.5), axis=(0.25, 0.0, 0.0), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 563, pyvista: wrong topology
# volume    0.195910671 (true 0.196948754): error -1.038e-03, tessellation -1.264e-03, bound 1.264e-03 -> tessellation
# area      3.53597186 (true 3.55579128): error -1.982e-02, tessellation -2.063e-02 -> tessellation
# hausdorff mesh->true 2.408e-03, true->mesh 2.408e-03, tessellation 2.408e-03 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_563():
    p0 = Cylinder(center=(0.5, 0.25, 0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(0.5, 0.5, 0.5), axis=(0.25, 0.0, 0.0), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 564, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 7.34738191): error -7.347e+00, tessellation -1.721e-01, bound 1.721e-01 -> wrong
# area      0 (true 37.8359406): error -3.784e+01, tessellation -2.384e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 8.937e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 1) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_564():
    p0 = Cone(center=(-0.25, -0.75, 0.0), axis=(0.0, 0.0, 1.75), radius=0.75)
    p1 = Torus(center=(1.0, 1.0, 0.5), axis=(1.0, 0.0, 0.0), major=2.0, minor=0.4)
    tree = Union(p0, p1)
    return tree


# case 565, pyvista: wrong topology
# volume    12.2982237 (true 12.6272888): error -3.291e-01, tessellation -3.294e-01, bound 3.310e-01 -> tessellation
# area      62.4144967 (true 62.7932016): error -3.787e-01, tessellation -3.790e-01 -> tessellation
# hausdorff mesh->true 8.938e-03, true->mesh 8.937e-03, tessellation 8.937e-03 -> tessellation
# topology  1 components, genus 2.5, watertight False, winding consistent False (true: 1, genus 2) -> wrong
# verdict   WRONG: topology
def case_565():
    p0 = Torus(center=(-0.25, -0.75, 0.0), axis=(0.0, 0.0, 1.0), major=2.0, minor=0.4)
    p1 = Torus(center=(1.0, 1.0, 0.5), axis=(1.0, 0.0, 0.0), major=2.0, minor=0.4)
    tree = Union(p0, p1)
    return tree


# case 569, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 6.41524286): error -6.415e+00, tessellation -1.681e-01, bound 1.681e-01 -> wrong
# area      0 (true 33.556655): error -3.356e+01, tessellation -2.301e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 8.938e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 2) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_569():
    p0 = Torus(center=(-0.25, -0.75, 0.5), axis=(0.0, 0.0, 1.0), major=2.0, minor=0.4)
    p1 = Torus(center=(-0.25, -0.75, 0.5), axis=(0.0, 0.0, 1.0), major=0.5, minor=0.1)
    tree = Union(p0, p1)
    return tree


# case 576, pyvista: hung over 120 s
def case_576():
    p0 = Ellipsoid(center=(0.5, -0.25, -1.0), radii=(1.0, 1.0, 2.0))
    p1 = Sphere(center=(0.0, 0.75, -1.0), radius=1.0)
    n2 = Difference(p0, p1)
    p3 = Torus(center=(1.0, 0.5, -0.75), axis=(0.0, 0.0, 1.0), major=2.25, minor=0.7875)
    p4 = Cylinder(center=(0.25, -0.25, -0.75), axis=(0.0, 0.0, 1.75), radius=0.75)
    n5 = Difference(p3, p4)
    p6 = Box(center=(1.149519052838329, -0.49102540378443876, -1.0), size=(1.5, 0.25, 1.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    n7 = Difference(n5, p6)
    tree = Intersection(n2, n7)
    return tree


# case 577, pyvista: wrong area, hausdorff, topology
# volume    0.189165043 (true 0.235571571): error -4.641e-02, tessellation -1.592e-02, bound 1.457e+00 -> tessellation
# area      4.66894657 (true 3.49227424): error +1.177e+00, tessellation -1.210e-01 -> wrong
# hausdorff mesh->true 1.627e+00, true->mesh 2.808e-02, tessellation 2.808e-02 -> wrong
# topology  6 components, genus 4.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_577():
    p0 = Ellipsoid(center=(0.5, -0.25, -1.0), radii=(1.0, 1.0, 2.0))
    p1 = Sphere(center=(0.0, 0.75, -1.0), radius=1.75)
    n2 = Difference(p0, p1)
    p3 = Torus(center=(1.0, 0.5, -0.75), axis=(0.0, 0.0, 1.0), major=2.25, minor=0.7875)
    p4 = Cylinder(center=(0.25, -0.25, -0.75), axis=(0.0, 0.0, 1.75), radius=0.75)
    n5 = Difference(p3, p4)
    p6 = Box(center=(1.149519052838329, -0.49102540378443876, -1.0), size=(1.5, 0.25, 1.5), orientation=((0.8660254037844387, -0.49999999999999994, 0.0), (0.49999999999999994, 0.8660254037844387, 0.0), (0.0, 0.0, 1.0)))
    n7 = Difference(n5, p6)
    tree = Intersection(n2, n7)
    return tree


# case 582, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_582():
    p0 = Sphere(center=(0.0, 0.75, -1.0), radius=1.75)
    p1 = Sphere(center=(0.0, 0.75, -1.0), radius=1.75)
    n2 = Difference(p0, p1)
    p3 = Torus(center=(1.0, 0.5, -0.75), axis=(0.0, 0.0, 1.0), major=2.25, minor=0.7875)
    p4 = Cylinder(center=(0.25, -0.25, -0.75), axis=(0.0, 0.0, 1.75), radius=0.75)
    n5 = Difference(p3, p4)
    p6 = Torus(center=(1.0, 0.5, -0.75), axis=(0.0, 0.0, 1.0), major=2.25, minor=0.7875)
    n7 = Difference(n5, p6)
    tree = Difference(n2, n7)
    return tree


# case 583, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.724942769): error -7.249e-01, tessellation -1.076e-02, bound 1.702e-02 -> wrong
# area      0 (true 13.6058407): error -1.361e+01, tessellation -7.072e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 5.290e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 2) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_583():
    p0 = Cone(center=(-0.75, 0.0, -0.75), axis=(0.25, 0.0, 0.0), radius=1.25)
    p1 = Torus(center=(-0.25, 0.0, -0.25), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.75, minor=0.15000000000000002)
    n2 = Union(p0, p1)
    p3 = Truncus(center=(0.5, 1.0, 0.75), axis=(0.5, 0.0, 0.0), r1=0.75, r2=0.75)
    tree = Difference(n2, p3)
    return tree


# case 584, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.721457158): error -7.215e-01, tessellation -1.074e-02, bound 1.702e-02 -> wrong
# area      0 (true 13.727371): error -1.373e+01, tessellation -7.434e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 4.089e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 2) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_584():
    p0 = Cone(center=(-0.75, 0.5, -0.75), axis=(0.25, 0.0, 0.0), radius=1.25)
    p1 = Torus(center=(-0.25, 0.0, -0.25), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.75, minor=0.15000000000000002)
    n2 = Union(p0, p1)
    p3 = Truncus(center=(0.5, 1.0, 0.75), axis=(0.5, 0.0, 0.0), r1=0.75, r2=0.75)
    tree = Difference(n2, p3)
    return tree


# case 585, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.01598147): error -1.016e+00, tessellation -1.263e-02, bound 1.324e-02 -> wrong
# area      0 (true 17.6183619): error -1.762e+01, tessellation -9.615e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 4.398e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 2) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_585():
    p0 = Cone(center=(-0.75, 0.5, -0.75), axis=(0.25, 0.0, 0.0), radius=1.25)
    p1 = Torus(center=(-0.25, 0.0, -0.25), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.75, minor=0.15000000000000002)
    n2 = Union(p0, p1)
    p3 = Cone(center=(0.5, 1.0, 0.75), axis=(0.5, 0.0, 0.0), radius=0.75)
    tree = Union(n2, p3)
    return tree


# case 586, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.41060996): error -1.411e+00, tessellation -1.487e-02, bound 1.586e-02 -> wrong
# area      0 (true 17.8453709): error -1.785e+01, tessellation -1.019e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.313e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 2) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_586():
    p0 = Cone(center=(-0.75, 0.5, -0.75), axis=(0.5, 0.0, 0.0), radius=1.25)
    p1 = Torus(center=(-0.25, 0.0, -0.25), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.75, minor=0.15000000000000002)
    n2 = Union(p0, p1)
    p3 = Cone(center=(0.5, 1.0, 0.75), axis=(0.5, 0.0, 0.0), radius=0.75)
    tree = Union(n2, p3)
    return tree


# case 587, pyvista: crashed (exit code -11)
def case_587():
    p0 = Cone(center=(-0.75, 0.5, -0.75), axis=(0.5, 0.0, 0.0), radius=1.25)
    p1 = Torus(center=(-0.25, 0.0, -0.25), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.75, minor=0.15000000000000002)
    n2 = Union(p0, p1)
    p3 = Torus(center=(-0.25, 0.0, -0.25), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.75, minor=0.15000000000000002)
    tree = Union(n2, p3)
    return tree


# case 588, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.447297322): error -4.473e-01, tessellation -9.087e-03, bound 1.829e-02 -> wrong
# area      0 (true 5.9492388): error -5.949e+00, tessellation -3.361e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.352e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 1) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_588():
    p0 = Cone(center=(-0.75, 0.5, -0.75), axis=(0.5, 0.0, 0.0), radius=0.5)
    p1 = Torus(center=(-0.25, 0.0, -0.25), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.75, minor=0.15000000000000002)
    n2 = Union(p0, p1)
    p3 = Torus(center=(-0.25, 0.0, -0.25), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.75, minor=0.15000000000000002)
    tree = Union(n2, p3)
    return tree


# case 590, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.000785398163): error -7.854e-04, tessellation -5.037e-06, bound 1.099e+00 -> tessellation
# area      0 (true 1.57393792): error -1.574e+00, tessellation -1.008e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.773e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_590():
    p0 = Cylinder(center=(0.25, 0.75, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Sphere(center=(0.75, -0.75, -0.25), radius=1.75)
    p2 = Sphere(center=(-0.25, 1.0, 1.0), radius=1.5)
    p3 = Torus(center=(-1.0, -1.0, 0.75), axis=(0.0, 1.0, 0.0), major=1.25, minor=0.625)
    n4 = Union(p2, p3)
    n5 = Union(p1, n4)
    p6 = Torus(center=(0.25, -1.0, 0.5), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.75, minor=0.15000000000000002)
    n7 = Intersection(n5, p6)
    tree = Difference(p0, n7)
    return tree


# case 591, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.000785398163): error -7.854e-04, tessellation -5.037e-06, bound 1.099e+00 -> tessellation
# area      0 (true 1.57393792): error -1.574e+00, tessellation -1.008e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.157e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_591():
    p0 = Cylinder(center=(0.25, 0.75, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Sphere(center=(0.75, -0.75, -0.25), radius=1.75)
    p2 = Sphere(center=(-0.25, 1.0, 1.0), radius=1.5)
    p3 = Torus(center=(-1.0, -1.0, 0.75), axis=(0.0, 1.0, 0.0), major=1.25, minor=0.625)
    n4 = Union(p2, p3)
    n5 = Union(p1, n4)
    p6 = Torus(center=(0.25, -1.0, 0.5), axis=(0.0, 1.0, 0.0), major=0.75, minor=0.15000000000000002)
    n7 = Intersection(n5, p6)
    tree = Difference(p0, n7)
    return tree


# case 592, pyvista: crashed (exit code -11)
def case_592():
    p0 = Cylinder(center=(0.25, 0.75, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Sphere(center=(0.75, -0.75, -0.25), radius=1.75)
    p2 = Sphere(center=(-0.25, 1.0, 1.0), radius=1.5)
    p3 = Torus(center=(-1.0, -1.0, 0.75), axis=(0.0, 1.0, 0.0), major=1.25, minor=0.625)
    n4 = Union(p2, p3)
    n5 = Union(p1, n4)
    p6 = Torus(center=(-1.0, -1.0, 0.75), axis=(0.0, 1.0, 0.0), major=1.25, minor=0.625)
    n7 = Intersection(n5, p6)
    tree = Difference(p0, n7)
    return tree


# case 593, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.000785398163): error -7.854e-04, tessellation -5.037e-06, bound 1.363e+00 -> tessellation
# area      0 (true 1.57393792): error -1.574e+00, tessellation -1.008e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.164e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_593():
    p0 = Cylinder(center=(0.25, 0.75, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Sphere(center=(0.75, -0.75, -0.25), radius=1.75)
    p2 = Sphere(center=(-0.25, 1.0, 1.0), radius=1.5)
    p3 = Torus(center=(-1.0, -1.0, 0.75), axis=(0.0, 1.0, 0.0), major=1.25, minor=0.625)
    n4 = Union(p2, p3)
    n5 = Union(p1, n4)
    p6 = Torus(center=(-1.0, -1.0, 1.0), axis=(0.0, 1.0, 0.0), major=1.25, minor=0.625)
    n7 = Intersection(n5, p6)
    tree = Difference(p0, n7)
    return tree


# case 595, pyvista: wrong area, hausdorff, topology
# volume    0 (true 0.000785398163): error -7.854e-04, tessellation -5.037e-06, bound 7.110e-01 -> tessellation
# area      0 (true 1.57393792): error -1.574e+00, tessellation -1.008e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.020e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_595():
    p0 = Cylinder(center=(0.25, 0.75, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Sphere(center=(-0.25, 1.0, 1.0), radius=1.5)
    p2 = Torus(center=(-0.25, 1.0, 1.0), axis=(0.0, 0.0, 1.0), major=1.75, minor=0.35000000000000003)
    p3 = Sphere(center=(0.75, 0.25, 1.0), radius=0.5)
    n4 = Union(p2, p3)
    n5 = Union(p1, n4)
    p6 = Torus(center=(-1.0, -1.0, 1.0), axis=(0.0, 1.0, 0.0), major=1.25, minor=0.625)
    n7 = Intersection(n5, p6)
    tree = Difference(p0, n7)
    return tree


# case 598, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 3.31798006): error -3.318e+00, tessellation -2.422e-02, bound 2.317e-01 -> wrong
# area      0 (true 22.0443066): error -2.204e+01, tessellation -1.192e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.143e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 1) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_598():
    p0 = Cylinder(center=(0.25, 0.25, -0.5), axis=(0.25, 0.0, 0.0), radius=1.25)
    p1 = Sphere(center=(0.0, -0.75, -0.75), radius=1.0)
    n2 = Intersection(p0, p1)
    p3 = Cone(center=(-0.25, 0.0, 0.25), axis=(1.75, 1.75, 1.75), radius=1.75)
    p4 = Truncus(center=(0.0, -0.5, -0.5), axis=(0.3, -0.5, 1.0), r1=1.5, r2=0.25)
    n5 = Difference(p3, p4)
    p6 = Truncus(center=(0.75, 0.0, 0.25), axis=(0.0, 1.0, 0.0), r1=1.0, r2=2.0)
    n7 = Intersection(n5, p6)
    tree = Union(n2, n7)
    return tree


# case 599, pyvista: hung over 120 s
def case_599():
    p0 = Cylinder(center=(0.25, 0.25, -0.5), axis=(0.25, 0.0, 0.0), radius=1.25)
    p1 = Sphere(center=(0.0, -0.75, 0.0), radius=1.0)
    n2 = Intersection(p0, p1)
    p3 = Cone(center=(-0.25, 0.0, 0.25), axis=(1.75, 1.75, 1.75), radius=1.75)
    p4 = Truncus(center=(0.0, -0.5, -0.5), axis=(0.3, -0.5, 1.0), r1=1.5, r2=0.25)
    n5 = Difference(p3, p4)
    p6 = Truncus(center=(0.75, 0.0, 0.25), axis=(0.0, 1.0, 0.0), r1=1.0, r2=2.0)
    n7 = Intersection(n5, p6)
    tree = Union(n2, n7)
    return tree


# case 603, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 13.123346): error -1.312e+01, tessellation -1.224e-01, bound 2.597e-01 -> wrong
# area      0 (true 39.3660218): error -3.937e+01, tessellation -1.729e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.189e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_603():
    p0 = Cylinder(center=(0.25, 0.25, -0.5), axis=(0.25, 0.0, 0.0), radius=1.25)
    p1 = Sphere(center=(0.0, -0.75, 0.0), radius=1.0)
    n2 = Union(p0, p1)
    p3 = Cone(center=(-0.25, 0.0, 0.25), axis=(1.75, 1.75, 1.75), radius=1.75)
    n4 = Union(n2, p3)
    p5 = Sphere(center=(0.0, -0.5, -0.5), radius=1.0)
    p6 = Truncus(center=(0.0, -0.75, 0.0), axis=(0.25, 0.25, 0.25), r1=0.25, r2=0.75)
    n7 = Intersection(p5, p6)
    tree = Union(n4, n7)
    return tree


# case 605, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_605():
    p0 = Cone(center=(-0.75, -1.0, 0.25), axis=(0.0, 0.75, 0.0), radius=1.75)
    p1 = Box(center=(-0.25, -0.25, -0.5), size=(1.0, 1.0, 0.25))
    p2 = Box(center=(-0.25, -0.25, -0.5), size=(1.0, 1.0, 0.25))
    n3 = Difference(p1, p2)
    tree = Intersection(p0, n3)
    return tree


# case 606, pyvista: hung over 120 s
def case_606():
    p0 = Cone(center=(-0.75, -1.0, 0.25), axis=(0.0, 0.75, 0.0), radius=1.75)
    p1 = Box(center=(-0.25, -0.25, -0.5), size=(1.0, 1.0, 0.25))
    p2 = Box(center=(0.5, -0.25, -0.5), size=(1.0, 1.0, 0.25))
    n3 = Difference(p1, p2)
    tree = Intersection(p0, n3)
    return tree


# case 607, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_607():
    p0 = Cone(center=(-0.75, -1.0, 0.25), axis=(0.0, 0.75, 0.0), radius=1.75)
    p1 = Box(center=(0.5, -0.25, -0.5), size=(1.0, 1.0, 0.25))
    p2 = Box(center=(0.5, -0.25, -0.5), size=(1.0, 1.0, 0.25))
    n3 = Difference(p1, p2)
    tree = Intersection(p0, n3)
    return tree


# case 608, trimesh-manifold: wrong topology
# volume    9.82681689e-11 (true 0): error +9.827e-11, tessellation +0.000e+00, bound 3.085e-02 -> exact
# area      0.0511328632 (true 0): error +5.113e-02, tessellation +3.904e-02 -> tessellation
# hausdorff mesh->true 3.299e-03, true->mesh 0.000e+00, tessellation 3.215e-03 -> tessellation
# topology  4 components, genus 1.5, watertight False, winding consistent False (true: 0, genus 0) -> wrong
# verdict   WRONG: topology
def case_608():
    p0 = Cone(center=(-0.75, -1.0, 0.25), axis=(0.0, 0.75, 0.0), radius=1.75)
    p1 = Box(center=(0.5, -0.25, -0.5), size=(1.0, 1.0, 0.25))
    p2 = Cone(center=(-0.75, -1.0, 0.25), axis=(0.0, 0.75, 0.0), radius=1.75)
    n3 = Difference(p1, p2)
    tree = Intersection(p0, n3)
    return tree


# case 609, trimesh-manifold: wrong topology
# volume    6.85279333e-11 (true 0): error +6.853e-11, tessellation +0.000e+00, bound 3.085e-02 -> exact
# area      0.0557063022 (true 0): error +5.571e-02, tessellation +9.709e-02 -> tessellation
# hausdorff mesh->true 3.053e-03, true->mesh 0.000e+00, tessellation 3.044e-03 -> tessellation
# topology  4 components, genus 1.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
# case 609, pyvista: crashed (exit code -11)
def case_609():
    p0 = Cone(center=(-0.75, -1.0, 0.25), axis=(0.0, 0.75, 0.0), radius=1.75)
    p1 = Box(center=(1.0, -0.75, 0.25), size=(1.0, 1.0, 0.25))
    p2 = Cone(center=(-0.75, -1.0, 0.25), axis=(0.0, 0.75, 0.0), radius=1.75)
    n3 = Difference(p1, p2)
    tree = Intersection(p0, n3)
    return tree


# case 610, pyvista: crashed (exit code -11)
def case_610():
    p0 = Cone(center=(-0.75, -1.0, 0.25), axis=(0.0, 0.75, 0.0), radius=1.75)
    p1 = Box(center=(1.0, -0.75, 0.25), size=(1.0, 1.0, 0.25))
    p2 = Cone(center=(-0.75, -1.0, 0.25), axis=(0.0, 0.75, 0.0), radius=1.75)
    n3 = Intersection(p1, p2)
    tree = Intersection(p0, n3)
    return tree


# case 611, pyvista: wrong hausdorff, topology
# volume    8.44667499 (true 8.42161038): error +2.506e-02, tessellation -2.929e-02, bound 1.548e-01 -> tessellation
# area      32.8062457 (true 32.8250704): error -1.882e-02, tessellation -1.692e-01 -> tessellation
# hausdorff mesh->true 4.081e-02, true->mesh 1.278e-02, tessellation 1.278e-02 -> wrong
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: hausdorff, topology
def case_611():
    p0 = Truncus(center=(-1.0, -0.25, 1.0), axis=(0.44999999999999996, -0.75, 1.5), r1=0.5, r2=2.0)
    p1 = Sphere(center=(-1.0, 0.5, 0.0), radius=1.0)
    tree = Difference(p0, p1)
    return tree


# case 614, pyvista: wrong topology
# volume    1.02978279 (true 1.02938211): error +4.007e-04, tessellation -2.227e-03, bound 1.004e-01 -> tessellation
# area      7.53683193 (true 7.56364918): error -2.682e-02, tessellation -4.154e-02 -> tessellation
# hausdorff mesh->true 1.252e-02, true->mesh 1.178e-02, tessellation 1.178e-02 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_614():
    p0 = Truncus(center=(-1.0, -0.25, 1.0), axis=(0.15, -0.25, 0.5), r1=0.5, r2=1.0)
    p1 = Sphere(center=(-1.0, 0.5, 0.0), radius=1.0)
    tree = Difference(p0, p1)
    return tree


# case 616, pyvista: wrong hausdorff, topology
# volume    0.00789989068 (true 0.00486793696): error +3.032e-03, tessellation +1.080e-03, bound 1.004e-01 -> tessellation
# area      0.891765348 (true 0.803144074): error +8.862e-02, tessellation +8.180e-02 -> tessellation
# hausdorff mesh->true 1.992e-02, true->mesh 1.193e-02, tessellation 1.205e-02 -> wrong
# topology  1 components, genus 2, watertight False, winding consistent False (true: 1, genus 1) -> wrong
# verdict   WRONG: hausdorff, topology
def case_616():
    p0 = Truncus(center=(-1.0, -0.25, 1.0), axis=(0.15, -0.25, 0.5), r1=0.5, r2=1.0)
    p1 = Sphere(center=(-1.0, -0.25, 1.0), radius=1.0)
    tree = Difference(p0, p1)
    return tree


# case 617, pyvista: wrong hausdorff, topology
# volume    0.0062614087 (true 0.00352870091): error +2.733e-03, tessellation +7.803e-04, bound 9.867e-02 -> tessellation
# area      0.784019158 (true 0.706120059): error +7.790e-02, tessellation +7.107e-02 -> tessellation
# hausdorff mesh->true 1.826e-02, true->mesh 1.162e-02, tessellation 1.205e-02 -> wrong
# topology  1 components, genus 2, watertight False, winding consistent False (true: 1, genus 1) -> wrong
# verdict   WRONG: hausdorff, topology
def case_617():
    p0 = Truncus(center=(-1.0, -0.25, 1.0), axis=(0.15, -0.25, 0.5), r1=0.25, r2=1.0)
    p1 = Sphere(center=(-1.0, -0.25, 1.0), radius=1.0)
    tree = Difference(p0, p1)
    return tree


# case 618, pyvista: wrong volume, area, hausdorff, topology
# volume    2.79992507 (true 0.11594712): error +2.684e+00, tessellation -1.365e-02, bound 6.899e-01 -> wrong
# area      6.46264494 (true 1.97697665): error +4.486e+00, tessellation -1.385e-01 -> wrong
# hausdorff mesh->true 1.748e+00, true->mesh 2.065e-02, tessellation 2.180e-02 -> wrong
# topology  11 components, genus 9.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_618():
    p0 = Sphere(center=(0.0, 1.0, 1.0), radius=1.0)
    p1 = Cylinder(center=(1.0, 0.5, 0.25), axis=(0.15, -0.25, 0.5), radius=2.0)
    p2 = Sphere(center=(-1.0, 0.75, -1.0), radius=1.75)
    p3 = Cylinder(center=(-1.0, 1.0, 0.5), axis=(0.0, 0.0, 1.0), radius=1.5)
    p4 = Ellipsoid(center=(0.0, 1.0, 0.75), radii=(0.25, 0.25, 0.5))
    n5 = Union(p3, p4)
    n6 = Intersection(p2, n5)
    n7 = Intersection(p1, n6)
    tree = Intersection(p0, n7)
    return tree


# case 619, pyvista: wrong volume, area, hausdorff, topology
# volume    2.82902187 (true 0.115950596): error +2.713e+00, tessellation -1.365e-02, bound 6.987e-01 -> wrong
# area      6.98598032 (true 1.97698342): error +5.009e+00, tessellation -1.385e-01 -> wrong
# hausdorff mesh->true 1.748e+00, true->mesh 2.443e-02, tessellation 2.443e-02 -> wrong
# topology  10 components, genus 8.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_619():
    p0 = Sphere(center=(0.0, 1.0, 1.0), radius=1.0)
    p1 = Cylinder(center=(1.0, 0.5, 0.25), axis=(0.15, -0.25, 0.5), radius=2.0)
    p2 = Sphere(center=(-1.0, 0.75, -1.0), radius=1.75)
    p3 = Cylinder(center=(-1.0, 1.0, 0.5), axis=(0.0, 0.0, 1.0), radius=1.5)
    p4 = Ellipsoid(center=(0.0, 1.0, 0.75), radii=(0.25, 1.0, 0.5))
    n5 = Union(p3, p4)
    n6 = Intersection(p2, n5)
    n7 = Intersection(p1, n6)
    tree = Intersection(p0, n7)
    return tree


# case 620, pyvista: wrong volume, area, hausdorff, topology
# volume    1.39828131 (true 0.0180427532): error +1.380e+00, tessellation -3.496e-03, bound 7.456e-01 -> wrong
# area      7.74034715 (true 0.476188027): error +7.264e+00, tessellation -5.836e-02 -> wrong
# hausdorff mesh->true 2.475e+00, true->mesh 2.157e-02, tessellation 2.157e-02 -> wrong
# topology  11 components, genus 9.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_620():
    p0 = Sphere(center=(0.0, 1.0, 1.0), radius=1.0)
    p1 = Ellipsoid(center=(1.0, 0.5, 0.25), radii=(1.0, 0.5, 2.0))
    p2 = Sphere(center=(-1.0, 0.75, -1.0), radius=1.75)
    p3 = Cylinder(center=(-1.0, 1.0, 0.5), axis=(0.0, 0.0, 1.0), radius=1.5)
    p4 = Ellipsoid(center=(0.0, 1.0, 0.75), radii=(0.25, 1.0, 0.5))
    n5 = Union(p3, p4)
    n6 = Intersection(p2, n5)
    n7 = Intersection(p1, n6)
    tree = Intersection(p0, n7)
    return tree


# case 621, pyvista: wrong volume, area, hausdorff, topology
# volume    1.39828131 (true 0.018042848): error +1.380e+00, tessellation -3.497e-03, bound 7.369e-01 -> wrong
# area      7.90326743 (true 0.476188432): error +7.427e+00, tessellation -5.836e-02 -> wrong
# hausdorff mesh->true 2.412e+00, true->mesh 2.203e-02, tessellation 2.203e-02 -> wrong
# topology  11 components, genus 9, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_621():
    p0 = Sphere(center=(0.0, 1.0, 1.0), radius=1.0)
    p1 = Ellipsoid(center=(1.0, 0.5, 0.25), radii=(1.0, 0.5, 2.0))
    p2 = Sphere(center=(-1.0, 0.75, -1.0), radius=1.75)
    p3 = Cylinder(center=(-1.0, 1.0, 0.5), axis=(0.0, 0.0, 1.0), radius=1.5)
    p4 = Ellipsoid(center=(0.0, 1.0, 0.75), radii=(0.25, 0.25, 0.5))
    n5 = Union(p3, p4)
    n6 = Intersection(p2, n5)
    n7 = Intersection(p1, n6)
    tree = Intersection(p0, n7)
    return tree


# case 622, pyvista: wrong topology
# volume    0.978612778 (true 1.04168606): error -6.307e-02, tessellation -6.302e-02, bound 7.369e-01 -> tessellation
# area      7.47238885 (true 7.69289811): error -2.205e-01, tessellation -2.277e-01 -> tessellation
# hausdorff mesh->true 3.290e-02, true->mesh 2.274e-02, tessellation 2.274e-02 -> tessellation
# topology  3 components, genus 2.5, watertight False, winding consistent False (true: 1, genus 0) -> wrong
# verdict   WRONG: topology
def case_622():
    p0 = Sphere(center=(0.0, 1.0, 1.0), radius=1.0)
    p1 = Ellipsoid(center=(1.0, 0.5, 0.25), radii=(1.0, 0.5, 2.0))
    p2 = Sphere(center=(-1.0, 0.75, -1.0), radius=1.75)
    p3 = Cylinder(center=(-1.0, 1.0, 0.5), axis=(0.0, 0.0, 1.0), radius=1.5)
    p4 = Ellipsoid(center=(0.0, 1.0, 0.75), radii=(0.25, 0.25, 0.5))
    n5 = Union(p3, p4)
    n6 = Intersection(p2, n5)
    n7 = Union(p1, n6)
    tree = Intersection(p0, n7)
    return tree


# case 623, pyvista: wrong hausdorff, topology
# volume    1.43773369 (true 1.5049302): error -6.720e-02, tessellation -6.427e-02, bound 7.369e-01 -> tessellation
# area      9.53384339 (true 9.69401538): error -1.602e-01, tessellation -1.913e-01 -> tessellation
# hausdorff mesh->true 6.239e-02, true->mesh 2.299e-02, tessellation 2.299e-02 -> wrong
# topology  3 components, genus 5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: hausdorff, topology
def case_623():
    p0 = Sphere(center=(0.0, 1.0, 0.0), radius=1.0)
    p1 = Ellipsoid(center=(1.0, 0.5, 0.25), radii=(1.0, 0.5, 2.0))
    p2 = Sphere(center=(-1.0, 0.75, -1.0), radius=1.75)
    p3 = Cylinder(center=(-1.0, 1.0, 0.5), axis=(0.0, 0.0, 1.0), radius=1.5)
    p4 = Ellipsoid(center=(0.0, 1.0, 0.75), radii=(0.25, 0.25, 0.5))
    n5 = Union(p3, p4)
    n6 = Intersection(p2, n5)
    n7 = Union(p1, n6)
    tree = Intersection(p0, n7)
    return tree


# case 630, pyvista: crashed (exit code -11)
def case_630():
    p0 = Sphere(center=(1.0, 0.5, 0.0), radius=2.0)
    p1 = Cylinder(center=(1.0, -1.0, 1.0), axis=(0.0, 1.5, 0.0), radius=1.0)
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(1.0, -1.0, 1.0), axis=(0.0, 1.5, 0.0), radius=1.0)
    p4 = Cylinder(center=(1.0, -1.0, 1.0), axis=(0.0, 1.5, 0.0), radius=1.0)
    n5 = Intersection(p3, p4)
    tree = Intersection(n2, n5)
    return tree


# case 631, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.998845443): error -9.988e-01, tessellation -3.399e-02, bound 8.392e-01 -> wrong
# area      0 (true 5.86200463): error -5.862e+00, tessellation -1.110e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 2.364e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_631():
    p0 = Sphere(center=(1.0, 0.5, 0.0), radius=2.0)
    p1 = Cylinder(center=(1.0, -1.0, 1.0), axis=(0.0, 1.5, 0.0), radius=1.0)
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.0, -1.0, 1.0), axis=(0.0, 1.5, 0.0), radius=1.0)
    p4 = Cylinder(center=(1.0, -1.0, 1.0), axis=(0.0, 1.5, 0.0), radius=1.0)
    n5 = Intersection(p3, p4)
    tree = Intersection(n2, n5)
    return tree


# case 632, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_632():
    p0 = Cylinder(center=(-0.5, 0.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Box(center=(-0.25, 0.75, 0.25), size=(1.0, 1.0, 0.0001))
    p2 = Cone(center=(0.5, 0.75, 1.0), axis=(0.25, 0.25, 0.25), radius=0.75)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Box(center=(0.17677669529663698, 1.2374368670764582, 0.0), size=(0.5, 2.0, 0.75), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 633, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_633():
    p0 = Cylinder(center=(-0.5, 0.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Box(center=(-0.25, 0.75, 0.25), size=(1.0, 1.0, 0.0001))
    p2 = Cone(center=(0.5, 0.75, 1.0), axis=(0.25, 0.25, 0.25), radius=0.75)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Box(center=(0.17677669529663698, 1.2374368670764582, 0.0), size=(0.25, 0.75, 0.25), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 634, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_634():
    p0 = Cylinder(center=(-0.5, 0.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(-0.25, 0.75, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Cone(center=(0.5, 0.75, 1.0), axis=(0.25, 0.25, 0.25), radius=0.75)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Box(center=(0.17677669529663698, 1.2374368670764582, 0.0), size=(0.25, 0.75, 0.25), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 635, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_635():
    p0 = Cylinder(center=(-0.5, 0.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(0.75, 0.75, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Cone(center=(0.5, 0.75, 1.0), axis=(0.25, 0.25, 0.25), radius=0.75)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Box(center=(0.17677669529663698, 1.2374368670764582, 0.0), size=(0.25, 0.75, 0.25), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 636, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_636():
    p0 = Cylinder(center=(-0.5, 0.0, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(0.75, 0.75, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Cone(center=(0.5, 0.75, 1.0), axis=(0.25, 0.25, 0.25), radius=0.75)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Box(center=(0.17677669529663698, 1.2374368670764582, 0.0), size=(1.0, 0.75, 0.25), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 637, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_637():
    p0 = Cylinder(center=(0.75, 0.75, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(0.75, 0.75, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Cone(center=(0.5, 0.75, 1.0), axis=(0.25, 0.25, 0.25), radius=0.75)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Box(center=(0.17677669529663698, 1.2374368670764582, 0.0), size=(1.0, 0.75, 0.25), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 638, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_638():
    p0 = Cylinder(center=(0.75, 0.75, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(0.75, 0.75, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Cone(center=(0.5, 0.75, 1.0), axis=(0.25, 0.25, 0.25), radius=0.75)
    n3 = Intersection(p1, p2)
    n4 = Union(p0, n3)
    p5 = Box(center=(0.17677669529663698, 1.2374368670764582, 0.0), size=(0.25, 0.75, 0.25), orientation=((0.7071067811865476, -0.7071067811865475, 0.0), (0.7071067811865475, 0.7071067811865476, 0.0), (0.0, 0.0, 1.0)))
    tree = Difference(n4, p5)
    return tree


# case 639, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.64761086): error -1.648e+00, tessellation +1.554e-02, bound 1.458e-01 -> wrong
# area      0 (true 11.0565013): error -1.106e+01, tessellation +4.348e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.044e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_639():
    p0 = Box(center=(0.49794978843022397, 0.9365073455143291, 1.0), size=(1.5, 1.25, 1.25), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Torus(center=(0.25, 0.5, -0.25), axis=(0.0, 1.0, 0.0), major=1.25, minor=0.4375)
    p2 = Torus(center=(0.5, -1.0, -0.5), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.5, minor=0.25)
    n3 = Union(p1, p2)
    tree = Difference(p0, n3)
    return tree


# case 640, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 6.37037023): error -6.370e+00, tessellation -1.128e-01, bound 1.458e-01 -> wrong
# area      0 (true 27.3658083): error -2.737e+01, tessellation -1.119e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.051e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 1, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_640():
    p0 = Box(center=(0.49794978843022397, 0.9365073455143291, 1.0), size=(1.5, 1.25, 1.25), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Torus(center=(0.25, 0.5, -0.25), axis=(0.0, 1.0, 0.0), major=1.25, minor=0.4375)
    n2 = Union(p0, p1)
    p3 = Torus(center=(0.5, -1.0, -0.5), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.5, minor=0.25)
    tree = Difference(n2, p3)
    return tree


# case 641, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 6.3703724): error -6.370e+00, tessellation -1.128e-01, bound 1.458e-01 -> wrong
# area      0 (true 27.3658083): error -2.737e+01, tessellation -1.119e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.050e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 1, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_641():
    p0 = Box(center=(0.49794978843022397, 0.9365073455143291, 1.0), size=(1.5, 1.25, 1.25), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Torus(center=(0.25, 0.5, -0.25), axis=(0.0, 1.0, 0.0), major=1.25, minor=0.4375)
    n2 = Union(p0, p1)
    p3 = Torus(center=(0.5, -1.0, -0.5), axis=(0.0, 1.0, 0.0), major=0.5, minor=0.25)
    tree = Difference(n2, p3)
    return tree


# case 642, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 10.742122): error -1.074e+01, tessellation -2.461e-01, bound 2.901e-01 -> wrong
# area      0 (true 34.5738451): error -3.457e+01, tessellation -1.798e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.588e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 1, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_642():
    p0 = Box(center=(0.49794978843022397, 0.9365073455143291, 1.0), size=(1.5, 1.25, 1.25), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Torus(center=(0.25, 0.5, -0.25), axis=(0.0, 1.0, 0.0), major=1.25, minor=0.625)
    n2 = Union(p0, p1)
    p3 = Torus(center=(0.5, -1.0, -0.5), axis=(0.0, 1.0, 0.0), major=0.5, minor=0.25)
    tree = Difference(n2, p3)
    return tree


# case 645, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_645():
    p0 = Box(center=(-0.75, -0.75, -0.75), size=(1.5, 1.75, 0.25))
    p1 = Cylinder(center=(0.75, 0.25, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Cone(center=(0.0, -1.0, -0.75), axis=(0.0, 0.0, 1.5), radius=1.75)
    n3 = Difference(p1, p2)
    p4 = Sphere(center=(-0.5, -0.5, -0.25), radius=0.75)
    p5 = Ellipsoid(center=(-0.5, 0.75, -1.0), radii=(0.25, 1.75, 0.75))
    n6 = Intersection(p4, p5)
    n7 = Intersection(n3, n6)
    tree = Difference(p0, n7)
    return tree


# case 646, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_646():
    p0 = Box(center=(-0.75, -0.75, -0.75), size=(1.5, 1.75, 0.25))
    p1 = Cylinder(center=(0.75, 0.25, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Cone(center=(0.0, -1.0, -0.75), axis=(0.0, 0.0, 1.5), radius=1.75)
    n3 = Difference(p1, p2)
    p4 = Sphere(center=(0.0, 0.0, 0.25), radius=0.75)
    p5 = Ellipsoid(center=(-0.5, 0.75, -1.0), radii=(0.25, 1.75, 0.75))
    n6 = Intersection(p4, p5)
    n7 = Intersection(n3, n6)
    tree = Difference(p0, n7)
    return tree


# case 647, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_647():
    p0 = Box(center=(0.0, -0.75, -0.75), size=(1.5, 1.75, 0.25))
    p1 = Cylinder(center=(0.75, 0.25, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Cone(center=(0.0, -1.0, -0.75), axis=(0.0, 0.0, 1.5), radius=1.75)
    n3 = Difference(p1, p2)
    p4 = Sphere(center=(0.0, 0.0, 0.25), radius=0.75)
    p5 = Ellipsoid(center=(-0.5, 0.75, -1.0), radii=(0.25, 1.75, 0.75))
    n6 = Intersection(p4, p5)
    n7 = Intersection(n3, n6)
    tree = Difference(p0, n7)
    return tree


# case 648, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_648():
    p0 = Box(center=(0.0, -0.75, -0.75), size=(1.5, 1.75, 0.25))
    p1 = Cylinder(center=(0.75, 0.25, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Cone(center=(0.0, -1.0, -0.75), axis=(0.0, 0.0, 1.5), radius=1.75)
    n3 = Difference(p1, p2)
    p4 = Sphere(center=(0.0, 0.0, 0.25), radius=0.75)
    p5 = Ellipsoid(center=(-0.5, 0.75, -1.0), radii=(0.25, 1.25, 0.75))
    n6 = Intersection(p4, p5)
    n7 = Intersection(n3, n6)
    tree = Difference(p0, n7)
    return tree


# case 649, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_649():
    p0 = Box(center=(0.0, -0.75, -0.75), size=(1.5, 1.75, 0.25))
    p1 = Cylinder(center=(0.75, 0.25, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Cone(center=(0.0, -1.0, -0.75), axis=(0.0, 0.0, 1.5), radius=1.75)
    n3 = Difference(p1, p2)
    p4 = Sphere(center=(0.0, 0.0, 0.25), radius=0.75)
    p5 = Ellipsoid(center=(-0.5, 0.75, -1.0), radii=(0.25, 1.5, 0.75))
    n6 = Intersection(p4, p5)
    n7 = Intersection(n3, n6)
    tree = Difference(p0, n7)
    return tree


# case 650, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_650():
    p0 = Box(center=(0.0, -0.75, -0.75), size=(1.5, 1.75, 0.25))
    p1 = Cylinder(center=(0.75, 0.25, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p2 = Cone(center=(0.0, -1.0, -0.75), axis=(0.0, 0.0, 1.5), radius=1.75)
    n3 = Difference(p1, p2)
    p4 = Sphere(center=(0.0, 0.75, 0.25), radius=0.75)
    p5 = Ellipsoid(center=(-0.5, 0.75, -1.0), radii=(0.25, 1.5, 0.75))
    n6 = Intersection(p4, p5)
    n7 = Intersection(n3, n6)
    tree = Difference(p0, n7)
    return tree


# case 657, pyvista: wrong hausdorff, topology
# volume    0.557111714 (true 0.535360536): error +2.175e-02, tessellation +1.889e-02, bound 7.632e-01 -> tessellation
# area      7.206844 (true 7.04650871): error +1.603e-01, tessellation +1.497e-01 -> tessellation
# hausdorff mesh->true 6.065e-02, true->mesh 1.761e-02, tessellation 1.817e-02 -> wrong
# topology  2 components, genus 1.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: hausdorff, topology
def case_657():
    p0 = Cylinder(center=(0.0, 0.0, -0.5), axis=(0.75, 0.0, 0.0), radius=1.0)
    p1 = Torus(center=(-0.75, 0.0, 0.75), axis=(0.0, 1.0, 0.0), major=1.75, minor=0.875)
    tree = Difference(p0, p1)
    return tree


# case 658, pyvista: wrong topology
# volume    2.32107 (true 2.32781756): error -6.748e-03, tessellation -1.359e-02, bound 3.256e-02 -> tessellation
# area      10.953386 (true 10.9820954): error -2.871e-02, tessellation -4.694e-02 -> tessellation
# hausdorff mesh->true 6.343e-03, true->mesh 6.264e-03, tessellation 6.269e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
def case_658():
    p0 = Cylinder(center=(0.0, 0.0, -0.5), axis=(0.75, 0.0, 0.0), radius=1.0)
    p1 = Torus(center=(-0.75, 0.0, 0.75), axis=(0.0, 1.0, 0.0), major=0.5, minor=0.25)
    tree = Difference(p0, p1)
    return tree


# case 659, pyvista: wrong hausdorff, topology
# volume    2.24180557 (true 2.25215954): error -1.035e-02, tessellation -1.172e-02, bound 3.256e-02 -> tessellation
# area      11.2150801 (true 11.2586319): error -4.355e-02, tessellation -4.719e-02 -> tessellation
# hausdorff mesh->true 3.168e-02, true->mesh 2.582e-02, tessellation 6.355e-03 -> wrong
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: hausdorff, topology
def case_659():
    p0 = Cylinder(center=(0.0, 0.0, -0.5), axis=(0.75, 0.0, 0.0), radius=1.0)
    p1 = Torus(center=(-0.75, 0.0, 0.25), axis=(0.0, 1.0, 0.0), major=0.5, minor=0.25)
    tree = Difference(p0, p1)
    return tree


# case 660, pyvista: wrong hausdorff, topology
# volume    2.3431446 (true 2.3426934): error +4.512e-04, tessellation -1.480e-02, bound 1.637e-02 -> tessellation
# area      11.0976815 (true 11.0985458): error -8.643e-04, tessellation -5.016e-02 -> tessellation
# hausdorff mesh->true 3.536e-02, true->mesh 4.815e-03, tessellation 4.815e-03 -> wrong
# topology  2 components, genus 1, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: hausdorff, topology
def case_660():
    p0 = Cylinder(center=(0.0, 0.0, -0.5), axis=(0.75, 0.0, 0.0), radius=1.0)
    p1 = Cylinder(center=(-0.75, 0.0, 0.25), axis=(0.0, 0.25, 0.0), radius=0.5)
    tree = Difference(p0, p1)
    return tree


# case 662, pyvista: wrong volume, area, hausdorff, topology
# volume    -1.05330468 (true 1.09804564): error -2.151e+00, tessellation -3.767e-03, bound 3.022e-02 -> wrong
# area      9.67049206 (true 7.64050932): error +2.030e+00, tessellation -1.761e-02 -> wrong
# hausdorff mesh->true 6.762e-01, true->mesh 1.993e-01, tessellation 4.815e-03 -> wrong
# topology  9 components, genus 31.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_662():
    p0 = Cylinder(center=(0.0, 0.0, -0.5), axis=(0.75, 0.0, 0.0), radius=1.0)
    p1 = Cylinder(center=(0.0, 0.75, -0.5), axis=(0.75, 0.0, 0.0), radius=1.0)
    tree = Difference(p0, p1)
    return tree


# case 666, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_666():
    p0 = Sphere(center=(-0.25, -0.25, 0.5), radius=0.25)
    p1 = Cylinder(center=(0.75, -1.0, -0.5), axis=(1.5, 1.5, 1.5), radius=1.25)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(0.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0), radius=0.001)
    p4 = Truncus(center=(-0.25, 0.25, 0.5), axis=(1.75, 0.0, 0.0), r1=1.25, r2=1.75)
    p5 = Cylinder(center=(0.75, 0.5, -0.5), axis=(0.0, 0.0, 1.0), radius=0.001)
    n6 = Union(p4, p5)
    n7 = Difference(p3, n6)
    tree = Intersection(n2, n7)
    return tree


# case 671, pyvista: wrong topology
# volume    12.8829144 (true 13.1710095): error -2.881e-01, tessellation -2.880e-01, bound 2.983e-01 -> tessellation
# area      29.0227475 (true 29.3417078): error -3.190e-01, tessellation -3.192e-01 -> tessellation
# hausdorff mesh->true 1.848e-02, true->mesh 1.875e-02, tessellation 1.877e-02 -> tessellation
# topology  1 components, genus 1, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
def case_671():
    p0 = Sphere(center=(-0.5, 0.75, 0.5), radius=0.5)
    p1 = Ellipsoid(center=(-1.0, -0.25, 0.0), radii=(1.75, 1.0, 1.75))
    tree = Union(p0, p1)
    return tree


# case 672, pyvista: wrong topology
# volume    4.06171769 (true 4.15156196): error -8.984e-02, tessellation -8.973e-02, bound 9.357e-02 -> tessellation
# area      16.2099805 (true 16.3678766): error -1.579e-01, tessellation -1.593e-01 -> tessellation
# hausdorff mesh->true 1.538e-02, true->mesh 1.531e-02, tessellation 1.555e-02 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
def case_672():
    p0 = Sphere(center=(-0.5, 0.75, 0.5), radius=0.5)
    p1 = Ellipsoid(center=(-1.0, -0.25, 0.0), radii=(1.75, 1.0, 0.5))
    tree = Union(p0, p1)
    return tree


# case 673, pyvista: wrong topology
# volume    1.14593919 (true 1.1710621): error -2.512e-02, tessellation -2.520e-02, bound 2.632e-02 -> tessellation
# area      7.639833 (true 7.70740678): error -6.757e-02, tessellation -6.654e-02 -> tessellation
# hausdorff mesh->true 1.013e-02, true->mesh 1.018e-02, tessellation 1.025e-02 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
def case_673():
    p0 = Ellipsoid(center=(-0.5, 0.75, 0.5), radii=(0.5, 1.25, 0.25))
    p1 = Sphere(center=(0.0, 0.0, 1.0), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 675, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.17809725): error -1.178e+00, tessellation -2.632e-02, bound 2.632e-02 -> wrong
# area      0 (true 8.0337342): error -8.034e+00, tessellation -9.485e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.052e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_675():
    p0 = Ellipsoid(center=(-0.5, 0.75, 0.5), radii=(0.5, 1.25, 0.25))
    p1 = Sphere(center=(0.5, 0.0, 0.25), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 676, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.719948316): error -7.199e-01, tessellation -1.608e-02, bound 1.608e-02 -> wrong
# area      0 (true 5.67753971): error -5.678e+00, tessellation -6.614e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.064e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_676():
    p0 = Ellipsoid(center=(-0.5, 0.75, 0.5), radii=(0.5, 1.25, 0.25))
    p1 = Sphere(center=(0.5, 0.0, 0.25), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 677, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.719948316): error -7.199e-01, tessellation -1.608e-02, bound 1.608e-02 -> wrong
# area      0 (true 5.67753971): error -5.678e+00, tessellation -6.614e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.056e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_677():
    p0 = Ellipsoid(center=(-0.5, 0.75, 0.0), radii=(0.5, 1.25, 0.25))
    p1 = Sphere(center=(0.5, 0.0, 0.25), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 678, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_678():
    p0 = Box(center=(-0.25, -0.5, 0.0), size=(1.0, 1.0, 0.0001))
    p1 = Truncus(center=(0.0, 0.0, 0.5), axis=(0.0, 0.5, 0.0), r1=0.75, r2=0.25)
    p2 = Cylinder(center=(-0.25, 0.0, -0.25), axis=(1.0, 1.0, 1.0), radius=0.001)
    n3 = Intersection(p1, p2)
    p4 = Cylinder(center=(-1.0, 0.5, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Intersection(n3, p4)
    tree = Union(p0, n5)
    return tree


# case 679, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_679():
    p0 = Cylinder(center=(-0.25, -0.5, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Truncus(center=(0.0, 0.0, 0.5), axis=(0.0, 0.5, 0.0), r1=0.75, r2=0.25)
    p2 = Cylinder(center=(-0.25, 0.0, -0.25), axis=(1.0, 1.0, 1.0), radius=0.001)
    n3 = Intersection(p1, p2)
    p4 = Cylinder(center=(-1.0, 0.5, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Intersection(n3, p4)
    tree = Union(p0, n5)
    return tree


# case 680, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_680():
    p0 = Cylinder(center=(-0.25, -0.5, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Truncus(center=(0.0, -0.5, 0.5), axis=(0.0, 0.5, 0.0), r1=0.75, r2=0.25)
    p2 = Cylinder(center=(-0.25, 0.0, -0.25), axis=(1.0, 1.0, 1.0), radius=0.001)
    n3 = Intersection(p1, p2)
    p4 = Cylinder(center=(-1.0, 0.5, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Intersection(n3, p4)
    tree = Union(p0, n5)
    return tree


# case 681, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_681():
    p0 = Cylinder(center=(-0.25, -0.5, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Truncus(center=(0.0, -0.5, 0.5), axis=(0.0, 0.5, 0.0), r1=0.75, r2=0.25)
    p2 = Cylinder(center=(-0.25, 0.0, -0.25), axis=(1.0, 1.0, 1.0), radius=0.001)
    n3 = Intersection(p1, p2)
    p4 = Cylinder(center=(0.25, 0.5, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Intersection(n3, p4)
    tree = Union(p0, n5)
    return tree


# case 682, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_682():
    p0 = Cylinder(center=(-0.25, -0.5, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Truncus(center=(0.0, -0.5, 0.5), axis=(0.0, 0.5, 0.0), r1=0.75, r2=0.25)
    p2 = Cylinder(center=(-0.25, 0.0, -0.25), axis=(1.0, 1.0, 1.0), radius=0.001)
    n3 = Intersection(p1, p2)
    p4 = Cylinder(center=(0.25, -0.25, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Intersection(n3, p4)
    tree = Union(p0, n5)
    return tree


# case 683, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_683():
    p0 = Cylinder(center=(0.25, -0.25, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Truncus(center=(0.0, -0.5, 0.5), axis=(0.0, 0.5, 0.0), r1=0.75, r2=0.25)
    p2 = Cylinder(center=(-0.25, 0.0, -0.25), axis=(1.0, 1.0, 1.0), radius=0.001)
    n3 = Intersection(p1, p2)
    p4 = Cylinder(center=(0.25, -0.25, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Intersection(n3, p4)
    tree = Union(p0, n5)
    return tree


# case 684, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_684():
    p0 = Cylinder(center=(0.25, -0.25, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Truncus(center=(0.0, -0.5, 0.5), axis=(0.0, 0.5, 0.0), r1=0.75, r2=0.25)
    p2 = Cylinder(center=(-0.25, 0.0, -0.25), axis=(0.0, 1.0, 0.0), radius=0.001)
    n3 = Intersection(p1, p2)
    p4 = Cylinder(center=(0.25, -0.25, -0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Intersection(n3, p4)
    tree = Union(p0, n5)
    return tree


# case 692, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.04719755): error -1.047e+00, tessellation -2.339e-02, bound 2.339e-02 -> wrong
# area      0 (true 7.10888319): error -7.109e+00, tessellation -8.445e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 8.794e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_692():
    p0 = Sphere(center=(0.25, 0.25, -1.0), radius=0.5)
    p1 = Ellipsoid(center=(0.0, -0.75, -0.25), radii=(0.5, 0.25, 1.0))
    tree = Union(p0, p1)
    return tree


# case 694, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.04719755): error -1.047e+00, tessellation -2.339e-02, bound 2.339e-02 -> wrong
# area      0 (true 7.93458108): error -7.935e+00, tessellation -9.236e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 8.781e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_694():
    p0 = Ellipsoid(center=(0.0, 1.0, -0.25), radii=(0.5, 0.25, 1.0))
    p1 = Ellipsoid(center=(0.0, -0.75, -0.25), radii=(0.5, 0.25, 1.0))
    tree = Union(p0, p1)
    return tree


# case 695, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.654498469): error -6.545e-01, tessellation -1.462e-02, bound 1.462e-02 -> wrong
# area      0 (true 5.30969275): error -5.310e+00, tessellation -6.233e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 8.680e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_695():
    p0 = Ellipsoid(center=(0.0, 1.0, -0.25), radii=(0.5, 0.25, 1.0))
    p1 = Ellipsoid(center=(0.0, -0.75, -0.25), radii=(0.5, 0.25, 0.25))
    tree = Union(p0, p1)
    return tree


# case 696, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.654498469): error -6.545e-01, tessellation -1.462e-02, bound 1.462e-02 -> wrong
# area      0 (true 5.30969275): error -5.310e+00, tessellation -6.233e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 8.561e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_696():
    p0 = Ellipsoid(center=(0.0, 1.0, -0.25), radii=(0.5, 0.25, 1.0))
    p1 = Ellipsoid(center=(0.0, -0.25, -0.25), radii=(0.5, 0.25, 0.25))
    tree = Union(p0, p1)
    return tree


# case 697, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.392699082): error -3.927e-01, tessellation -8.772e-03, bound 8.772e-03 -> wrong
# area      0 (true 3.87349595): error -3.873e+00, tessellation -4.610e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 7.670e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_697():
    p0 = Ellipsoid(center=(0.0, 1.0, -0.25), radii=(0.25, 1.0, 0.25))
    p1 = Ellipsoid(center=(0.0, -0.25, -0.25), radii=(0.5, 0.25, 0.25))
    tree = Union(p0, p1)
    return tree


# case 706, pyvista: wrong topology
# volume    6.37297286 (true 6.41410927): error -4.114e-02, tessellation -4.114e-02, bound 4.113e-02 -> tessellation
# area      24.580007 (true 24.6726203): error -9.261e-02, tessellation -1.081e-01 -> tessellation
# hausdorff mesh->true 6.263e-03, true->mesh 8.322e-03, tessellation 8.322e-03 -> tessellation
# topology  1 components, genus 1, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
def case_706():
    p0 = Cone(center=(0.75, -0.75, -0.75), axis=(0.0, 2.0, 0.0), radius=1.75)
    p1 = Box(center=(1.0, -0.25, 0.25), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 707, pyvista: wrong topology
# volume    6.37295097 (true 6.41408404): error -4.113e-02, tessellation -4.113e-02, bound 4.113e-02 -> tessellation
# area      24.1250576 (true 24.2406271): error -1.156e-01, tessellation -1.156e-01 -> tessellation
# hausdorff mesh->true 6.312e-03, true->mesh 7.559e-03, tessellation 7.559e-03 -> tessellation
# topology  1 components, genus 0.5, watertight False, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
def case_707():
    p0 = Cone(center=(1.0, -0.25, 0.25), axis=(0.0, 2.0, 0.0), radius=1.75)
    p1 = Box(center=(1.0, -0.25, 0.25), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 708, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000100001693 (true 0.0001): error +1.693e-09, tessellation -7.345e-18, bound 2.204e-17 -> wrong
# area      2.00040001 (true 2.0004): error +6.771e-09, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from polygons) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_708():
    p0 = Box(center=(1.0, -0.25, 0.25), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(1.0, -0.25, 0.25), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 709, trimesh-manifold: wrong area, hausdorff
# volume    0.000175002962 (true 0.000175): error +2.962e-09, tessellation -1.285e-17, bound 2.204e-17 -> exact
# area      3.50055001 (true 3.50055): error +9.310e-09, tessellation -4.441e-16 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from polygons) -> exact
# verdict   WRONG: area, hausdorff
# case 709, pyvista: wrong area, hausdorff, topology
# volume    0.000175002962 (true 0.000175): error +2.962e-09, tessellation -1.285e-17, bound 2.204e-17 -> exact
# area      2.50035001 (true 3.50055): error -1.000e+00, tessellation -4.441e-16 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 9.999e-05, tessellation 5.509e-18 -> wrong
# topology  2 components, genus 2, watertight False, winding consistent True (true: 1, genus 0, from polygons) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_709():
    p0 = Box(center=(0.25, -0.25, 0.25), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(1.0, -0.25, 0.25), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 710, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000100001693 (true 0.0001): error +1.693e-09, tessellation -7.345e-18, bound 2.204e-17 -> wrong
# area      2.00040001 (true 2.0004): error +6.771e-09, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from polygons) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_710():
    p0 = Box(center=(0.25, -0.25, 0.25), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.25, -0.25, 0.25), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 711, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000200003386 (true 0.0002): error +3.386e-09, tessellation -2.204e-17, bound 2.204e-17 -> wrong
# area      4.00080001 (true 4.0008): error +1.354e-08, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from polygons) -> exact
# verdict   WRONG: volume, area, hausdorff
# case 711, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0002): error -2.000e-04, tessellation -2.204e-17, bound 2.204e-17 -> wrong
# area      0 (true 4.0008): error -4.001e+00, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 5.509e-18 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from polygons) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_711():
    p0 = Box(center=(0.25, -0.25, -0.25), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.25, -0.25, 0.25), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 712, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000100001693 (true 0.0001): error +1.693e-09, tessellation -7.345e-18, bound 2.204e-17 -> wrong
# area      2.00040001 (true 2.0004): error +6.771e-09, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from polygons) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_712():
    p0 = Box(center=(0.25, -0.25, -0.25), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(0.25, -0.25, -0.25), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 722, pyvista: wrong volume, area, hausdorff, topology
# volume    12.1492678 (true 5.49778744): error +6.651e+00, tessellation -3.526e-02, bound 1.432e-01 -> wrong
# area      24.8575909 (true 17.2787602): error +7.579e+00, tessellation -5.795e-02 -> wrong
# hausdorff mesh->true 7.500e-01, true->mesh 4.815e-03, tessellation 4.815e-03 -> wrong
# topology  50 components, genus 56, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_722():
    p0 = Cylinder(center=(0.25, 0.0, 1.0), axis=(1.75, 0.0, 0.0), radius=1.75)
    p1 = Cylinder(center=(0.25, 0.0, 1.0), axis=(1.75, 0.0, 0.0), radius=1.0)
    tree = Intersection(p0, p1)
    return tree


# case 723, pyvista: wrong area, hausdorff, topology
# volume    4.68216763 (true 4.71238898): error -3.022e-02, tessellation -3.022e-02, bound 7.052e-02 -> tessellation
# area      26.4554246 (true 15.7079633): error +1.075e+01, tessellation -5.543e-02 -> wrong
# hausdorff mesh->true 2.500e-01, true->mesh 4.815e-03, tessellation 4.815e-03 -> wrong
# topology  106 components, genus 116, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_723():
    p0 = Cylinder(center=(0.0, 0.0, 1.0), axis=(1.75, 0.0, 0.0), radius=1.0)
    p1 = Cylinder(center=(0.25, 0.0, 1.0), axis=(1.75, 0.0, 0.0), radius=1.0)
    tree = Intersection(p0, p1)
    return tree


# case 724, pyvista: wrong volume, area, hausdorff, topology
# volume    0.739405816 (true 0.343611696): error +3.958e-01, tessellation -2.204e-03, bound 3.746e-02 -> wrong
# area      3.58718968 (true 3.14159265): error +4.456e-01, tessellation -6.932e-03 -> wrong
# hausdorff mesh->true 7.500e-01, true->mesh 1.204e-03, tessellation 1.204e-03 -> wrong
# topology  46 components, genus 40.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_724():
    p0 = Cylinder(center=(0.25, 0.0, 1.0), axis=(1.75, 0.0, 0.0), radius=0.25)
    p1 = Cylinder(center=(0.25, 0.0, 1.0), axis=(1.75, 0.0, 0.0), radius=1.0)
    tree = Intersection(p0, p1)
    return tree


# case 727, trimesh-manifold: wrong volume
# volume    2.42098619 (true 2.42602316): error -5.037e-03, tessellation -5.037e-03, bound 5.037e-03 -> wrong
# area      15.9050583 (true 15.9435835): error -3.853e-02, tessellation -3.852e-02 -> tessellation
# hausdorff mesh->true 2.862e-03, true->mesh 3.298e-03, tessellation 3.298e-03 -> tessellation
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> exact
# verdict   WRONG: volume
# case 727, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 2.42602316): error -2.426e+00, tessellation -5.037e-03, bound 5.037e-03 -> wrong
# area      0 (true 15.9435835): error -1.594e+01, tessellation -3.852e-02 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 3.298e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_727():
    p0 = Box(center=(0.14618585236136838, -0.4781523779815177, 0.0), size=(1.25, 0.75, 1.75), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p1 = Cone(center=(-0.5, 1.0, 0.75), axis=(0.0, 0.75, 0.0), radius=1.0)
    tree = Union(p0, p1)
    return tree


# case 729, pyvista: wrong volume, area, hausdorff, topology
# volume    1.37340528 (true 1.5377352): error -1.643e-01, tessellation -9.099e-03, bound 1.007e-02 -> wrong
# area      11.1377095 (true 13.1172154): error -1.980e+00, tessellation -5.681e-02 -> wrong
# hausdorff mesh->true 2.773e-03, true->mesh 2.242e-01, tessellation 4.461e-03 -> wrong
# topology  4 components, genus 6, watertight False, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_729():
    p0 = Cone(center=(-0.5, 1.0, 0.75), axis=(0.0, 0.75, 0.0), radius=1.0)
    p1 = Cone(center=(1.0, 1.0, 0.75), axis=(0.0, 0.75, 0.0), radius=1.0)
    tree = Union(p0, p1)
    return tree


# case 730, pyvista: wrong volume, topology
# volume    0.3781008 (true 0.392426351): error -1.433e-02, tessellation -8.556e-03, bound 8.820e-03 -> wrong
# area      4.51907579 (true 4.52462334): error -5.548e-03, tessellation -1.824e-02 -> tessellation
# hausdorff mesh->true 4.202e-03, true->mesh 4.201e-03, tessellation 4.201e-03 -> tessellation
# topology  1 components, genus 2, watertight True, winding consistent False (true: 1, genus 2, from mesh) -> wrong
# verdict   WRONG: volume, topology
def case_730():
    p0 = Cone(center=(1.0, 1.0, -1.0), axis=(0.375, -0.625, 1.25), radius=0.25)
    p1 = Torus(center=(0.75, 1.0, -1.0), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.5, minor=0.175)
    tree = Union(p0, p1)
    return tree


# case 731, pyvista: wrong hausdorff, topology
# volume    0.374490149 (true 0.381696305): error -7.206e-03, tessellation -8.231e-03, bound 8.820e-03 -> tessellation
# area      4.38463332 (true 4.38808924): error -3.456e-03, tessellation -1.863e-02 -> tessellation
# hausdorff mesh->true 8.067e-03, true->mesh 4.193e-03, tessellation 4.193e-03 -> wrong
# topology  1 components, genus 3.5, watertight False, winding consistent False (true: 1, genus 2, from mesh) -> wrong
# verdict   WRONG: hausdorff, topology
def case_731():
    p0 = Cone(center=(0.75, 1.0, -1.0), axis=(0.375, -0.625, 1.25), radius=0.25)
    p1 = Torus(center=(0.75, 1.0, -1.0), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=0.5, minor=0.175)
    tree = Union(p0, p1)
    return tree


# case 732, pyvista: wrong volume, area, hausdorff, topology
# volume    0.103673164 (true 0.109749032): error -6.076e-03, tessellation -6.686e-04, bound 7.891e-04 -> wrong
# area      1.59220402 (true 1.6139755): error -2.177e-02, tessellation -4.093e-03 -> wrong
# hausdorff mesh->true 6.167e-03, true->mesh 6.730e-03, tessellation 1.171e-03 -> wrong
# topology  1 components, genus 3, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_732():
    p0 = Cone(center=(0.75, 1.0, -1.0), axis=(0.375, -0.625, 1.25), radius=0.25)
    p1 = Cone(center=(0.75, 1.0, -1.0), axis=(0.25, 0.25, 0.25), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 733, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.123045209): error -1.230e-01, tessellation -7.891e-04, bound 7.891e-04 -> wrong
# area      0 (true 1.93869058): error -1.939e+00, tessellation -5.632e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.175e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_733():
    p0 = Cone(center=(0.75, 1.0, -1.0), axis=(0.375, -0.625, 1.25), radius=0.25)
    p1 = Cone(center=(0.75, 1.0, 0.75), axis=(0.25, 0.25, 0.25), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 735, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.189409188): error -1.894e-01, tessellation -1.215e-03, bound 1.215e-03 -> wrong
# area      0 (true 2.69928392): error -2.699e+00, tessellation -6.543e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.186e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_735():
    p0 = Cone(center=(0.75, 1.0, -1.0), axis=(0.375, -0.625, 1.25), radius=0.25)
    p1 = Cone(center=(0.75, 0.0, -1.0), axis=(0.375, -0.625, 1.25), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 736, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.189409188): error -1.894e-01, tessellation -1.215e-03, bound 1.215e-03 -> wrong
# area      0 (true 2.69928392): error -2.699e+00, tessellation -6.543e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.185e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_736():
    p0 = Cone(center=(0.75, 1.0, -1.0), axis=(0.375, -0.625, 1.25), radius=0.25)
    p1 = Cone(center=(0.75, 0.25, -1.0), axis=(0.375, -0.625, 1.25), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 737, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_737():
    p0 = Ellipsoid(center=(0.0, -0.25, -0.5), radii=(1.5, 1.5, 1.5))
    p1 = Box(center=(0.5, 1.0, 1.0), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(1.0, 0.25, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p4 = Cylinder(center=(0.5, -0.5, -1.0), axis=(0.0, 0.5, 0.0), radius=1.25)
    n5 = Difference(p3, p4)
    n6 = Difference(n2, n5)
    p7 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(n6, p7)
    return tree


# case 738, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_738():
    p0 = Ellipsoid(center=(0.0, -0.25, -0.5), radii=(1.5, 1.5, 1.5))
    p1 = Box(center=(0.5, 1.0, 1.0), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p4 = Cylinder(center=(0.5, -0.5, -1.0), axis=(0.0, 0.5, 0.0), radius=1.25)
    n5 = Difference(p3, p4)
    n6 = Difference(n2, n5)
    p7 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(n6, p7)
    return tree


# case 739, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_739():
    p0 = Cylinder(center=(0.5, -0.5, -1.0), axis=(0.0, 0.5, 0.0), radius=1.25)
    p1 = Box(center=(0.5, 1.0, 1.0), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p4 = Cylinder(center=(0.5, -0.5, -1.0), axis=(0.0, 0.5, 0.0), radius=1.25)
    n5 = Difference(p3, p4)
    n6 = Difference(n2, n5)
    p7 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(n6, p7)
    return tree


# case 740, trimesh-manifold: wrong area, hausdorff
# volume    4.99784946e-05 (true 5e-05): error -2.151e-08, tessellation +1.685e-15, bound 3.149e-02 -> tessellation
# area      1.00029987 (true 1.0003): error -1.290e-07, tessellation +1.310e-14 -> wrong
# hausdorff mesh->true 5.131e-08, true->mesh 5.131e-08, tessellation 1.055e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> exact
# verdict   WRONG: area, hausdorff
def case_740():
    p0 = Cylinder(center=(0.5, -0.5, -1.0), axis=(0.0, 0.5, 0.0), radius=1.25)
    p1 = Box(center=(0.5, -0.5, -1.0), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p4 = Cylinder(center=(0.5, -0.5, -1.0), axis=(0.0, 0.5, 0.0), radius=1.25)
    n5 = Difference(p3, p4)
    n6 = Difference(n2, n5)
    p7 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(n6, p7)
    return tree


# case 741, trimesh-manifold: wrong area, hausdorff
# volume    4.99784946e-05 (true 5e-05): error -2.151e-08, tessellation +1.685e-15, bound 3.149e-02 -> tessellation
# area      1.00029987 (true 1.0003): error -1.290e-07, tessellation +1.310e-14 -> wrong
# hausdorff mesh->true 5.131e-08, true->mesh 5.131e-08, tessellation 1.055e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> exact
# verdict   WRONG: area, hausdorff
def case_741():
    p0 = Cylinder(center=(0.5, -0.5, -1.0), axis=(0.0, 0.5, 0.0), radius=1.25)
    p1 = Box(center=(0.5, -0.5, -1.0), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p4 = Cylinder(center=(-1.0, -0.5, -1.0), axis=(0.0, 0.5, 0.0), radius=1.25)
    n5 = Difference(p3, p4)
    n6 = Difference(n2, n5)
    p7 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(n6, p7)
    return tree


# case 742, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_742():
    p0 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Box(center=(0.5, -0.5, -1.0), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p4 = Cylinder(center=(-1.0, -0.5, -1.0), axis=(0.0, 0.5, 0.0), radius=1.25)
    n5 = Difference(p3, p4)
    n6 = Difference(n2, n5)
    p7 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(n6, p7)
    return tree


# case 743, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_743():
    p0 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Box(center=(0.5, -0.5, -1.0), size=(1.0, 1.0, 0.0001))
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    p4 = Cylinder(center=(0.0, -0.5, -1.0), axis=(0.0, 0.5, 0.0), radius=1.25)
    n5 = Difference(p3, p4)
    n6 = Difference(n2, n5)
    p7 = Cylinder(center=(0.75, -0.75, 0.75), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Difference(n6, p7)
    return tree


# case 751, trimesh-manifold: wrong volume
# volume    9.55945062 (true 9.6211525): error -6.170e-02, tessellation -6.170e-02, bound 6.170e-02 -> wrong
# area      30.5968209 (true 30.7378793): error -1.411e-01, tessellation -1.411e-01 -> tessellation
# hausdorff mesh->true 8.426e-03, true->mesh 8.427e-03, tessellation 8.427e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> exact
# verdict   WRONG: volume
# case 751, pyvista: wrong volume, topology
# volume    9.5547207 (true 9.6211525): error -6.643e-02, tessellation -6.170e-02, bound 6.170e-02 -> wrong
# area      30.6062807 (true 30.7378793): error -1.316e-01, tessellation -1.411e-01 -> tessellation
# hausdorff mesh->true 8.427e-03, true->mesh 8.427e-03, tessellation 8.427e-03 -> tessellation
# topology  1 components, genus 0, watertight True, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, topology
def case_751():
    p0 = Box(center=(-0.75, -1.0, 0.75), size=(1.0, 1.0, 0.0001))
    p1 = Cylinder(center=(-1.0, -1.0, -0.5), axis=(1.0, 0.0, 0.0), radius=1.75)
    tree = Union(p0, p1)
    return tree


# case 752, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.196449541): error -1.964e-01, tessellation -1.259e-03, bound 1.259e-03 -> wrong
# area      0 (true 3.96389541): error -3.964e+00, tessellation -5.041e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.204e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_752():
    p0 = Box(center=(-0.75, -1.0, 0.75), size=(1.0, 1.0, 0.0001))
    p1 = Cylinder(center=(-1.0, -1.0, -0.5), axis=(1.0, 0.0, 0.0), radius=0.25)
    tree = Union(p0, p1)
    return tree


# case 753, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000100016594 (true 0.0001): error +1.659e-08, tessellation -7.345e-18, bound 2.204e-17 -> wrong
# area      2.00040007 (true 2.0004): error +6.638e-08, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 8.297e-09, true->mesh 8.297e-09, tessellation 5.509e-18 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from polygons) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_753():
    p0 = Box(center=(-0.75, -1.0, 0.75), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.75, -1.0, 0.75), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 754, trimesh-manifold: wrong volume, area, hausdorff
# volume    0.000199973583 (true 0.0002): error -2.642e-08, tessellation +8.899e-17, bound 1.203e-16 -> wrong
# area      4.00079989 (true 4.0008): error -1.057e-07, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true 5.131e-08, true->mesh 5.131e-08, tessellation 1.055e-16 -> wrong
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from polygons) -> exact
# verdict   WRONG: volume, area, hausdorff
# case 754, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.0002): error -2.000e-04, tessellation +8.899e-17, bound 1.203e-16 -> wrong
# area      0 (true 4.0008): error -4.001e+00, tessellation +0.000e+00 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.055e-16 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from polygons) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_754():
    p0 = Box(center=(-0.75, -1.0, -1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.75, -1.0, 0.75), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 755, trimesh-manifold: wrong volume, area, hausdorff
# volume    9.99569893e-05 (true 0.0001): error -4.301e-08, tessellation +6.666e-17, bound 2.185e-16 -> wrong
# area      2.00039983 (true 2.0004): error -1.720e-07, tessellation +8.882e-16 -> wrong
# hausdorff mesh->true 5.131e-08, true->mesh 5.131e-08, tessellation 1.055e-16 -> wrong
# topology  1 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from polygons) -> exact
# verdict   WRONG: volume, area, hausdorff
def case_755():
    p0 = Box(center=(-0.75, -1.0, -1.0), size=(1.0, 1.0, 0.0001))
    p1 = Box(center=(-0.75, -1.0, -1.0), size=(1.0, 1.0, 0.0001))
    tree = Union(p0, p1)
    return tree


# case 761, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_761():
    p0 = Cylinder(center=(0.5, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    p1 = Box(center=(0.5, 0.5, -0.75), size=(1.0, 1.0, 0.0001))
    n2 = Difference(p0, p1)
    p3 = Cylinder(center=(0.5, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    n4 = Difference(n2, p3)
    p5 = Cone(center=(0.0, 1.0, 1.0), axis=(0.44999999999999996, -0.75, 1.5), radius=0.5)
    n6 = Union(n4, p5)
    p7 = Cylinder(center=(0.5, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Difference(n6, p7)
    return tree


# case 763, trimesh-manifold: wrong volume
# volume    0.130160169 (true 0.130999694): error -8.395e-04, tessellation -8.395e-04, bound 8.395e-04 -> wrong
# area      3.88703174 (true 3.8965189): error -9.487e-03, tessellation -9.487e-03 -> tessellation
# hausdorff mesh->true 1.668e-03, true->mesh 1.685e-03, tessellation 1.693e-03 -> tessellation
# topology  2 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> exact
# verdict   WRONG: volume
# case 763, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 0.130999694): error -1.310e-01, tessellation -8.395e-04, bound 8.395e-04 -> wrong
# area      0 (true 3.8965189): error -3.897e+00, tessellation -9.487e-03 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.693e-03 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 2, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_763():
    p0 = Box(center=(1.0, 0.0, 1.0), size=(1.0, 1.0, 0.0001))
    p1 = Cone(center=(-0.75, -0.5, 0.0), axis=(0.0, 0.5, 0.0), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 765, pyvista: wrong area, hausdorff, topology
# volume    0.188565287 (true 0.189613181): error -1.048e-03, tessellation -1.048e-03, bound 1.679e-03 -> tessellation
# area      1.83351632 (true 2.49332485): error -6.598e-01, tessellation -1.047e-02 -> wrong
# hausdorff mesh->true 1.687e-03, true->mesh 3.283e-01, tessellation 2.333e-03 -> wrong
# topology  1 components, genus 1, watertight False, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: area, hausdorff, topology
def case_765():
    p0 = Cone(center=(-0.75, -0.5, 0.0), axis=(0.0, 0.5, 0.0), radius=0.5)
    p1 = Cone(center=(-0.5, -0.5, 0.0), axis=(0.0, 0.5, 0.0), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 766, pyvista: wrong volume, area, hausdorff, topology
# volume    0.165762057 (true 0.240327986): error -7.457e-02, tessellation -1.338e-03, bound 1.679e-03 -> wrong
# area      2.62950801 (true 3.17168298): error -5.422e-01, tessellation -1.230e-02 -> wrong
# hausdorff mesh->true 1.682e-03, true->mesh 2.171e-01, tessellation 1.738e-03 -> wrong
# topology  6 components, genus 7.5, watertight False, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_766():
    p0 = Cone(center=(-0.75, -0.5, -0.5), axis=(0.0, 0.5, 0.0), radius=0.5)
    p1 = Cone(center=(-0.5, -0.5, 0.0), axis=(0.0, 0.5, 0.0), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 768, pyvista: wrong volume, area, hausdorff, topology
# volume    0.235983214 (true 0.232983424): error +3.000e-03, tessellation -1.281e-03, bound 1.679e-03 -> wrong
# area      2.59205465 (true 3.05085135): error -4.588e-01, tessellation -1.203e-02 -> wrong
# hausdorff mesh->true 1.658e-03, true->mesh 2.203e-01, tessellation 2.212e-03 -> wrong
# topology  3 components, genus 4.5, watertight False, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_768():
    p0 = Cone(center=(-0.5, -0.5, 0.0), axis=(0.0, 0.5, 0.0), radius=0.5)
    p1 = Cone(center=(-0.5, -0.5, 0.5), axis=(0.0, 0.5, 0.0), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 769, pyvista: wrong volume, area, hausdorff, topology
# volume    0.235983214 (true 0.232983424): error +3.000e-03, tessellation -1.281e-03, bound 1.679e-03 -> wrong
# area      2.59205465 (true 3.05085135): error -4.588e-01, tessellation -1.203e-02 -> wrong
# hausdorff mesh->true 1.684e-03, true->mesh 2.377e-01, tessellation 2.008e-03 -> wrong
# topology  3 components, genus 4.5, watertight False, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_769():
    p0 = Cone(center=(-0.5, -0.5, 0.5), axis=(0.0, 0.5, 0.0), radius=0.5)
    p1 = Cone(center=(-0.5, -0.5, 0.0), axis=(0.0, 0.5, 0.0), radius=0.5)
    tree = Union(p0, p1)
    return tree


# case 775, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_775():
    p0 = Sphere(center=(-0.25, -0.75, 0.0), radius=0.25)
    p1 = Cone(center=(0.0, 0.0, 0.0), axis=(0.0, 1.0, 0.0), radius=1.0)
    p2 = Cone(center=(0.0, 0.0, 0.0), axis=(0.0, 1.0, 0.0), radius=1.0)
    n3 = Difference(p1, p2)
    n4 = Difference(p0, n3)
    p5 = Sphere(center=(-0.25, -0.75, 0.0), radius=0.25)
    tree = Intersection(n4, p5)
    return tree


# case 777, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_777():
    p0 = Torus(center=(-1.0, 0.25, -1.0), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.0, minor=0.5)
    p1 = Sphere(center=(1.0, -0.75, -0.75), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(-1.0, 1.0, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.5, 0.5, 0.25), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Difference(n4, p5)
    return tree


# case 778, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_778():
    p0 = Torus(center=(-1.0, 0.25, -1.0), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.0, minor=0.5)
    p1 = Sphere(center=(1.0, -0.75, -0.75), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(-1.0, 0.25, -1.0), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.0, minor=0.5)
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.5, 0.5, 0.25), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Difference(n4, p5)
    return tree


# case 779, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_779():
    p0 = Torus(center=(-1.0, 0.25, -1.0), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.0, minor=0.5)
    p1 = Sphere(center=(1.0, -0.75, -0.75), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(-1.0, 0.25, -1.0), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.0, minor=0.5)
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.5, -1.0, 0.25), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Difference(n4, p5)
    return tree


# case 780, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_780():
    p0 = Torus(center=(-1.0, 0.25, -1.0), axis=(0.25916052767440806, -0.4319342127906801, 0.8638684255813602), major=1.0, minor=0.5)
    p1 = Sphere(center=(1.0, -0.75, -0.75), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(-1.0, 0.25, -1.0), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.0, minor=0.5)
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.5, -1.0, 0.25), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Difference(n4, p5)
    return tree


# case 781, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_781():
    p0 = Torus(center=(-1.0, 0.25, -1.0), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.0, minor=0.5)
    p1 = Sphere(center=(1.0, -0.75, -0.75), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(0.5, 0.25, -1.0), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.0, minor=0.5)
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.5, -1.0, 0.25), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Difference(n4, p5)
    return tree


# case 782, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_782():
    p0 = Torus(center=(1.0, -0.75, -0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.0, minor=0.5)
    p1 = Sphere(center=(1.0, -0.75, -0.75), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(0.5, 0.25, -1.0), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.0, minor=0.5)
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.5, -1.0, 0.25), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Difference(n4, p5)
    return tree


# case 783, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_783():
    p0 = Torus(center=(1.0, -0.75, -0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.0, minor=0.5)
    p1 = Sphere(center=(1.0, -0.75, -0.75), radius=0.5)
    n2 = Intersection(p0, p1)
    p3 = Torus(center=(1.0, -0.75, -0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.0, minor=0.5)
    n4 = Difference(n2, p3)
    p5 = Cylinder(center=(0.5, -1.0, 0.25), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Difference(n4, p5)
    return tree


# case 784, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 8.18123087): error -8.181e+00, tessellation -1.828e-01, bound 2.930e-01 -> wrong
# area      0 (true 19.6349541): error -1.963e+01, tessellation -2.392e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.610e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_784():
    p0 = Sphere(center=(1.0, -0.75, -0.75), radius=1.25)
    p1 = Cylinder(center=(0.5, -0.75, 0.0), axis=(1.0, 1.0, 1.0), radius=1.75)
    p2 = Cone(center=(0.0, 0.25, 0.25), axis=(0.525, -0.875, 1.75), radius=0.5)
    n3 = Intersection(p1, p2)
    tree = Difference(p0, n3)
    return tree


# case 785, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 8.18123087): error -8.181e+00, tessellation -1.828e-01, bound 2.576e-01 -> wrong
# area      0 (true 19.6349541): error -1.963e+01, tessellation -2.392e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.641e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_785():
    p0 = Sphere(center=(1.0, -0.75, -0.75), radius=1.25)
    p1 = Cylinder(center=(0.5, -0.75, 0.0), axis=(0.3, -0.5, 1.0), radius=1.75)
    p2 = Cone(center=(0.0, 0.25, 0.25), axis=(0.525, -0.875, 1.75), radius=0.5)
    n3 = Intersection(p1, p2)
    tree = Difference(p0, n3)
    return tree


# case 786, pyvista: crashed (exit code -11)
def case_786():
    p0 = Sphere(center=(1.0, -0.75, -0.75), radius=1.25)
    p1 = Cylinder(center=(0.5, -0.75, 0.0), axis=(0.3, -0.5, 1.0), radius=1.75)
    p2 = Sphere(center=(1.0, -0.75, -0.75), radius=1.25)
    n3 = Intersection(p1, p2)
    tree = Difference(p0, n3)
    return tree


# case 787, pyvista: crashed (exit code -11)
def case_787():
    p0 = Sphere(center=(1.0, -0.75, -0.75), radius=1.25)
    p1 = Cylinder(center=(0.5, -0.75, 0.0), axis=(0.3, -0.5, 1.0), radius=1.75)
    p2 = Sphere(center=(1.0, -0.75, -0.75), radius=1.25)
    n3 = Intersection(p1, p2)
    tree = Intersection(p0, n3)
    return tree


# case 789, pyvista: wrong volume, area, hausdorff, topology
# volume    0 (true 1.59351471): error -1.594e+00, tessellation -5.193e-02, bound 4.369e-01 -> wrong
# area      0 (true 7.99043394): error -7.990e+00, tessellation -1.515e-01 -> wrong
# hausdorff mesh->true inf, true->mesh inf, tessellation 1.631e-02 -> wrong
# topology  0 components, genus 0, watertight True, winding consistent True (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: volume, area, hausdorff, topology
def case_789():
    p0 = Sphere(center=(1.0, -0.75, -0.75), radius=1.25)
    p1 = Cylinder(center=(0.5, -0.75, 0.0), axis=(0.3, -0.5, 1.0), radius=1.75)
    p2 = Sphere(center=(0.0, -0.75, -0.75), radius=1.25)
    n3 = Intersection(p1, p2)
    tree = Intersection(p0, n3)
    return tree


# case 792, pyvista: wrong topology
# volume    0.600884763 (true 0.592151439): error +8.733e-03, tessellation -4.131e-03, bound 3.117e-02 -> tessellation
# area      4.1554276 (true 4.14532876): error +1.010e-02, tessellation -1.730e-02 -> tessellation
# hausdorff mesh->true 3.265e-03, true->mesh 3.161e-03, tessellation 3.231e-03 -> tessellation
# topology  12 components, genus 8.5, watertight False, winding consistent False (true: 1, genus 0, from mesh) -> wrong
# verdict   WRONG: topology
def case_792():
    p0 = Cone(center=(1.0, 1.0, 0.75), axis=(1.25, 0.0, 0.0), radius=0.75)
    p1 = Cone(center=(1.0, 1.0, 0.75), axis=(0.0, 1.75, 0.0), radius=1.5)
    tree = Intersection(p0, p1)
    return tree


# case 794, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_794():
    p0 = Sphere(center=(-0.75, -1.0, 0.25), radius=2.0)
    p1 = Box(center=(0.75, -0.5, 1.0), size=(1.0, 1.0, 0.0001))
    p2 = Box(center=(0.07309292618068419, -0.23907618899075886, -1.0), size=(0.25, 1.75, 0.5), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p3 = Sphere(center=(-0.25, -0.5, 0.25), radius=2.0)
    n4 = Difference(p2, p3)
    n5 = Difference(p1, n4)
    tree = Union(p0, n5)
    return tree


# case 795, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_795():
    p0 = Sphere(center=(-0.75, -1.0, 0.5), radius=2.0)
    p1 = Box(center=(0.75, -0.5, 1.0), size=(1.0, 1.0, 0.0001))
    p2 = Box(center=(0.07309292618068419, -0.23907618899075886, -1.0), size=(0.25, 1.75, 0.5), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p3 = Sphere(center=(-0.25, -0.5, 0.25), radius=2.0)
    n4 = Difference(p2, p3)
    n5 = Difference(p1, n4)
    tree = Union(p0, n5)
    return tree


# case 796, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_796():
    p0 = Sphere(center=(-0.75, -1.0, 0.5), radius=2.0)
    p1 = Box(center=(0.75, -0.5, 1.0), size=(1.0, 1.0, 0.0001))
    p2 = Box(center=(0.07309292618068419, -0.23907618899075886, -1.0), size=(0.25, 0.5, 0.5), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p3 = Sphere(center=(-0.25, -0.5, 0.25), radius=2.0)
    n4 = Difference(p2, p3)
    n5 = Difference(p1, n4)
    tree = Union(p0, n5)
    return tree


# case 797, trimesh-manifold: raised ValueError: Not all meshes are volumes!
def case_797():
    p0 = Sphere(center=(-0.75, -1.0, 0.5), radius=2.0)
    p1 = Box(center=(0.25, 0.5, 0.5), size=(1.0, 1.0, 0.0001))
    p2 = Box(center=(0.07309292618068419, -0.23907618899075886, -1.0), size=(0.25, 0.5, 0.5), orientation=((0.9563047559630354, -0.29237170472273677, 0.0), (0.29237170472273677, 0.9563047559630354, 0.0), (0.0, 0.0, 1.0)))
    p3 = Sphere(center=(-0.25, -0.5, 0.25), radius=2.0)
    n4 = Difference(p2, p3)
    n5 = Difference(p1, n4)
    tree = Union(p0, n5)
    return tree
