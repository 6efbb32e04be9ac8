"""Findings of benchmarks/engines.py (docs/testing_engines.md): each function rebuilds the tree
of one case (its number in the list the command draws); the comments say what was found."""

from isocsg import *  # noqa: F403


# case 4: over 60 s, skipped
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


# case 12: over 60 s, skipped
def case_12():
    p0 = Torus(center=(-1.0, -0.5, 0.0), axis=(0.0, 0.0, 1.0), major=2.25, minor=0.45)
    p1 = Torus(center=(-0.25, -0.5, 0.75), axis=(0.0, 1.0, 0.0), major=1.0, minor=0.35)
    n2 = Union(p0, p1)
    p3 = Torus(center=(-0.25, -0.5, 0.75), axis=(0.0, 1.0, 0.0), major=1.0, minor=0.35)
    tree = Intersection(n2, p3)
    return tree


# case 13: over 60 s, skipped
def case_13():
    p0 = Torus(center=(-0.25, -0.5, 0.75), axis=(0.0, 1.0, 0.0), major=1.0, minor=0.35)
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


# case 55: over 60 s, skipped
def case_55():
    p0 = Cylinder(center=(-0.75, 0.75, -1.0), axis=(0.22499999999999998, -0.375, 0.75), radius=0.25)
    p1 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    p2 = Cylinder(center=(-0.5, -0.5, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Difference(p1, p2)
    n4 = Intersection(p0, n3)
    p5 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Union(n4, p5)
    return tree


# case 56: over 60 s, skipped
def case_56():
    p0 = Cylinder(center=(-0.75, -0.5, -1.0), axis=(0.22499999999999998, -0.375, 0.75), radius=0.25)
    p1 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    p2 = Cylinder(center=(-0.5, -0.5, -0.5), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Difference(p1, p2)
    n4 = Intersection(p0, n3)
    p5 = Cylinder(center=(0.25, 0.25, 1.0), axis=(0.3, -0.5, 1.0), radius=0.001)
    tree = Union(n4, p5)
    return tree


# case 57: over 60 s, skipped
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


# case 61: over 60 s, skipped
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


# case 73: isocsg raised TypeError: intersection_all() got an unexpected keyword argument 'grid_size'
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


# case 86: over 60 s, skipped
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


# case 94: over 60 s, skipped
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


# case 126: over 60 s, skipped
def case_126():
    p0 = Sphere(center=(0.5, -1.0, -0.25), radius=0.5)
    p1 = Cylinder(center=(-0.75, -0.75, -1.0), axis=(1.75, 1.75, 1.75), radius=1.5)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-0.75, -0.75, -1.0), axis=(1.75, 1.75, 1.75), radius=1.5)
    tree = Union(n2, p3)
    return tree


# case 127: over 60 s, skipped
def case_127():
    p0 = Sphere(center=(0.5, -1.0, -0.25), radius=0.5)
    p1 = Cylinder(center=(-0.75, -0.75, -1.0), axis=(1.75, 1.75, 1.75), radius=1.5)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-0.75, -0.75, -1.0), axis=(0.25, 0.25, 0.25), radius=1.5)
    tree = Union(n2, p3)
    return tree


# case 128: over 60 s, skipped
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


# case 152: over 60 s, skipped
def case_152():
    p0 = Cylinder(center=(0.0, 1.0, 0.25), axis=(0.0, 0.5, 0.0), radius=0.25)
    p1 = Sphere(center=(0.0, 1.0, 0.25), radius=0.25)
    tree = Difference(p0, p1)
    return tree


# case 154: over 60 s, skipped
def case_154():
    p0 = Cylinder(center=(0.0, 1.0, 0.25), axis=(0.0, 0.5, 0.0), radius=0.25)
    p1 = Sphere(center=(0.0, 0.25, 0.25), radius=1.0)
    tree = Difference(p0, p1)
    return tree


# case 158: over 60 s, skipped
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


# case 174: over 120 s, skipped
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


# case 200: over 120 s, skipped
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


# case 201: over 60 s, skipped
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


# case 202: over 120 s, skipped
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


# case 227: over 60 s, skipped
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


# case 229: over 60 s, skipped
def case_229():
    p0 = Cylinder(center=(-0.25, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(-0.75, 0.5, -0.75), axis=(0.6, -1.0, 2.0), radius=1.75)
    p2 = Cylinder(center=(-0.25, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    n3 = Union(p1, p2)
    tree = Union(p0, n3)
    return tree


# case 230: over 120 s, skipped
def case_230():
    p0 = Cylinder(center=(-0.25, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p1 = Cylinder(center=(-0.75, 0.5, -0.75), axis=(0.6, -1.0, 2.0), radius=1.75)
    n2 = Union(p0, p1)
    p3 = Cylinder(center=(-0.25, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    tree = Union(n2, p3)
    return tree


# case 234: over 120 s, skipped
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


# case 235: over 120 s, skipped
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


# case 245: over 120 s, skipped
def case_245():
    p0 = Cylinder(center=(0.75, -0.5, 1.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    p1 = Cone(center=(0.75, -0.5, 1.0), axis=(0.0, 0.25, 0.0), radius=1.0)
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.75, -0.5, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p4 = Cylinder(center=(-1.0, -1.0, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Intersection(p3, p4)
    tree = Intersection(n2, n5)
    return tree


# case 246: over 120 s, skipped
def case_246():
    p0 = Cylinder(center=(0.75, -0.5, 1.0), axis=(0.0, 1.0, 0.0), radius=0.001)
    p1 = Cone(center=(0.75, -0.5, 1.0), axis=(0.0, 0.25, 0.0), radius=1.0)
    n2 = Intersection(p0, p1)
    p3 = Cylinder(center=(0.75, -0.5, 1.0), axis=(0.0, 0.0, 0.001), radius=0.5)
    p4 = Cylinder(center=(-1.0, -0.5, 0.25), axis=(0.0, 0.0, 0.001), radius=0.5)
    n5 = Intersection(p3, p4)
    tree = Intersection(n2, n5)
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


# case 279: over 120 s, skipped
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


# case 311: over 120 s, skipped
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


# case 319: over 120 s, skipped
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


# case 351: over 120 s, skipped
def case_351():
    p0 = Torus(center=(0.75, -1.0, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.25, minor=0.25)
    p1 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    p2 = Sphere(center=(0.25, 0.75, 0.75), radius=0.5)
    n3 = Difference(p1, p2)
    p4 = Sphere(center=(0.25, 0.75, 0.75), radius=0.5)
    n5 = Intersection(n3, p4)
    tree = Difference(p0, n5)
    return tree


# case 352: over 120 s, skipped
def case_352():
    p0 = Torus(center=(0.75, -1.0, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258), major=1.25, minor=0.25)
    p1 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    p2 = Sphere(center=(0.25, 0.75, 0.75), radius=0.5)
    n3 = Difference(p1, p2)
    p4 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    n5 = Intersection(n3, p4)
    tree = Difference(p0, n5)
    return tree


# case 354: over 120 s, skipped
def case_354():
    p0 = Cylinder(center=(0.5, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    p1 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    p2 = Sphere(center=(0.25, 0.75, 0.75), radius=0.5)
    n3 = Difference(p1, p2)
    p4 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
    n5 = Intersection(n3, p4)
    tree = Difference(p0, n5)
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
