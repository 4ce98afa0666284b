using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics.Casting;

// WorldCast, the shapes a piece tests: a cell's walls, floors and objects; an object's; walls and floor triangles.
internal static partial class WorldCast
{
    /// <summary>A cell's walls (ceilings named as such), floors and the objects standing in it, within the box.</summary>
    private static void Cell(ref SweptSphere ray, CellSurface cell, D3 offset, in Box box)
    {
        Walls(ref ray, cell.Walls, offset, in box, new Names(SurfaceKind.CellWall, SurfaceKind.CellCeiling, SurfaceKind.CellWall, cell.CellId));
        Floors(ref ray, cell.Floors, offset, in box, new ShapeName(SurfaceKind.CellFloor, cell.CellId));
        foreach (ObjectSurface o in cell.Objects)
        {
            Object(ref ray, o, offset, in box);
        }
    }

    private static void Object(ref SweptSphere ray, ObjectSurface o, D3 offset, in Box box)
    {
        Vector3 lo = o.BoundsMin, hi = o.BoundsMax;
        if (!box.Meets(new Vector2(lo.X, lo.Y), new Vector2(hi.X, hi.Y), lo.Z, hi.Z))
        {
            return;
        }

        SurfaceKind wall = o.IsBuilding ? SurfaceKind.BuildingShell : SurfaceKind.ObjectWall;
        Walls(ref ray, o.Walls, new Exact(o.Exact.Walls), offset, in box, new Names(wall, wall, SurfaceKind.Cylinder, o.ObjectId));
        ObjectFloors(ref ray, o, offset, in box);
    }

    /// <summary>An object's floor triangles whose bounds meet the box, at their exact corners (<see cref="ObjectSurface.Exact"/>).</summary>
    [SkipLocalsInit]
    private static void ObjectFloors(ref SweptSphere ray, ObjectSurface o, D3 offset, in Box box)
    {
        ReadOnlySpan<FloorTriangle> floors = o.Floors;
        D3[] corners = o.Exact.Floors;
        Span<D3> v = stackalloc D3[3];
        D3 rel = offset - ray.Start;
        for (int i = 0; i < floors.Length; i++)
        {
            ref readonly FloorTriangle f = ref floors[i];
            if (!box.Meets(f.Min, f.Max, f.ZMin, f.ZMax))
            {
                continue;
            }

            (v[0], v[1], v[2]) = (corners[3 * i] + rel, corners[(3 * i) + 1] + rel, corners[(3 * i) + 2] + rel);
            ray.Polygon(v, new ShapeName(SurfaceKind.ObjectFloor, o.ObjectId), SurfaceKind.ObjectFloor);
        }
    }

    /// <summary>What a cast meeting a wall names: a wall's kind, a face's facing down (a ceiling), a cylinder's, and the id.</summary>
    private readonly record struct Names(SurfaceKind Wall, SurfaceKind FacingDown, SurfaceKind Round, uint Id);

    /// <summary>Where a wall polygon's vertices come from, relative to the cast's start.</summary>
    private interface IVertices
    {
        D3 At(int index, D3 rel);
    }

    /// <summary>Vertices as the walls hold them, in float (cells' and movers' walls).</summary>
    private readonly struct Placed(Vector3[] vertices) : IVertices
    {
        public D3 At(int index, D3 rel)
        {
            Vector3 p = vertices[index];
            return new D3(p.X + rel.X, p.Y + rel.Y, p.Z + rel.Z);
        }
    }

    /// <summary>An object's vertices placed in double (<see cref="ObjectSurface.Exact"/>).</summary>
    private readonly struct Exact(D3[] vertices) : IVertices
    {
        public D3 At(int index, D3 rel) => vertices[index] + rel;
    }

    /// <summary>Wall polygons and cylinders whose bounds meet the box, at the vertices the walls hold.</summary>
    private static void Walls(ref SweptSphere ray, CellWalls walls, D3 offset, in Box box, Names names) =>
        Walls(ref ray, walls, new Placed(walls.Vertices), offset, in box, names);

    /// <summary>Wall polygons and cylinders whose bounds meet the box, at <paramref name="vertices"/>.</summary>
    [SkipLocalsInit] // the vertex buffer is written before it is read
    private static void Walls<TVertices>(ref SweptSphere ray, CellWalls walls, TVertices vertices, D3 offset, in Box box, Names names)
        where TVertices : struct, IVertices
    {
        WallPolygon[] polygons = walls.Polygons;
        WallExtent[] extents = walls.Extents;
        System.Runtime.Intrinsics.Vector128<float> query = WallExtent.Query(box.Lo, box.Hi);
        Span<D3> v = stackalloc D3[PhysicsConstants.MaxWallPolygonVertices];
        D3 rel = offset - ray.Start;
        for (int i = 0; i < polygons.Length; i++)
        {
            if (!extents[i].Meets(query, box.ZLo, box.ZHi))
            {
                continue;
            }

            ref readonly WallPolygon w = ref polygons[i];
            if (w.Radius > 0f)
            {
                ray.Cylinder(w.A.X + rel.X, w.A.Y + rel.Y, w.Radius, w.ZMin + rel.Z, w.ZMax + rel.Z, new ShapeName(names.Round, names.Id));
                continue;
            }

            for (int k = 0; k < w.Count; k++)
            {
                v[k] = vertices.At(w.First + k, rel);
            }

            ray.Polygon(v[..w.Count], new ShapeName(names.Wall, names.Id), names.FacingDown);
        }
    }

    /// <summary>Floor triangles whose bounds meet the box, each at the Z its plane gives its corners (as a mover stands on it), as <paramref name="name"/>.</summary>
    [SkipLocalsInit]
    private static void Floors(ref SweptSphere ray, ReadOnlySpan<FloorTriangle> floors, D3 offset, in Box box, ShapeName name)
    {
        Span<D3> v = stackalloc D3[3];
        D3 rel = offset - ray.Start;
        foreach (ref readonly FloorTriangle f in floors)
        {
            if (!box.Meets(f.Min, f.Max, f.ZMin, f.ZMax))
            {
                continue;
            }

            v[0] = Corner(in f, f.A, rel);
            v[1] = Corner(in f, f.B, rel);
            v[2] = Corner(in f, f.C, rel);
            ray.Polygon(v, name, name.Kind);
        }
    }

    private static D3 Corner(in FloorTriangle f, Vector2 p, D3 rel)
    {
        double z = f.PlaneZ + ((double)f.Gradient.X * ((double)p.X - f.PlanePoint.X)) + ((double)f.Gradient.Y * ((double)p.Y - f.PlanePoint.Y));
        z = Math.Clamp(z, f.ZMin, f.ZMax);
        return new D3(p.X + rel.X, p.Y + rel.Y, z + rel.Z);
    }
}
