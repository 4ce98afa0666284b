using System.Numerics;
using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Movers;
using AcDream.Core.Physics.Point;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Drawing;

/// <summary>
/// What an answer stands on, drawn after its move, as the report finds it: the floor triangle under its feet (the ground
/// probe at its centre) or, with footing, when that is not at its feet, the floor under its footprint that holds it.
/// </summary>
internal static class FootingDrawing
{
    /// <summary>How far a triangle's Z may be from the answer's and still be the one under it, metres (the ground tolerance's order).</summary>
    private const float Match = 1e-3f;

    public static void Draw<TSink>(in WorldFrame frame, ref Neighbourhood lands, in ResolveResult result, in MovementOptions options, ref TSink sink)
        where TSink : IDebugSink
    {
        if (!result.IsOnGround || result.Outcome == ResolveOutcome.Held
            || !Locator.TryFind(frame, ref lands, result.Position, result.CellId, out Place place))
        {
            return;
        }

        var at = new NearDrawing.At(frame, place.X, place.Y);
        Ground.TryUnder(ref lands, in place, result.Position.Z, PhysicsConstants.GroundTolerance, out float z, out SurfaceContact floor);
        if (z == result.Position.Z || !(options.InThreeD && options.Footing))
        {
            Under(in at, in place, floor, z, ref sink); // the ground under the centre holds it
        }
        else
        {
            const float tolerance = PhysicsConstants.GroundTolerance;
            float reach = options.Body!.Value.Radius * PhysicsConstants.SupportReach;
            Support support = Supports.Highest(ref lands, in place, -1, new Footprint(place.Local, reach, result.Position.Z - tolerance, result.Position.Z + tolerance));
            if (support.Found)
            {
                Held(in at, place.Entry, in support, place.Local, reach, ref sink);
            }
        }
    }

    /// <summary>The triangle of <paramref name="floor"/> under the place at <paramref name="z"/>.</summary>
    private static void Under<TSink>(in NearDrawing.At at, in Place place, SurfaceContact floor, float z, ref TSink sink)
        where TSink : IDebugSink
    {
        Vector2 p = place.Local;
        LandblockEntry entry = place.Entry;
        switch (floor.Kind)
        {
            case SurfaceKind.Terrain:
                Terrain(in at, entry.Terrain, p, floor.Id, ref sink);
                break;
            case SurfaceKind.CellFloor when place.CellIndex >= 0:
                On(in at, entry.Cells[place.CellIndex].Floors, p, z, floor.Id, ref sink);
                break;
            case SurfaceKind.ObjectFloor:
                foreach (ObjectSurface o in place.CellIndex >= 0 ? entry.Cells[place.CellIndex].Objects : entry.OutdoorObjects)
                {
                    if (o.ObjectId == floor.Id && On(in at, o.Floors, p, z, floor.Id, ref sink))
                    {
                        return;
                    }
                }

                break;
        }
    }

    /// <summary>The first of <paramref name="floors"/> under <paramref name="p"/> within <see cref="Match"/> of <paramref name="z"/>, drawn as the floor.</summary>
    private static bool On<TSink>(in NearDrawing.At at, ReadOnlySpan<FloorTriangle> floors, Vector2 p, float z, uint id, ref TSink sink)
        where TSink : IDebugSink
    {
        foreach (ref readonly FloorTriangle t in floors)
        {
            if (t.TrySample(p.X, p.Y, out float under) && MathF.Abs(under - z) <= Match)
            {
                NearDrawing.Triangle(in at, in t, DrawKind.Floor, id, ref sink);
                return true;
            }
        }

        return false;
    }

    /// <summary>The terrain triangle under <paramref name="p"/> (landblock-local), split as its cell is.</summary>
    private static void Terrain<TSink>(in NearDrawing.At at, TerrainSurface terrain, Vector2 p, uint id, ref TSink sink)
        where TSink : IDebugSink
    {
        const float size = PhysicsConstants.CellSize;
        int cx = CellIds.OutdoorColumn(p.X), cy = CellIds.OutdoorColumn(p.Y);
        double u = (p.X / (double)size) - cx, v = (p.Y / (double)size) - cy;
        terrain.Corners(cx, cy, out double hsw, out double hnw, out double hse, out double hne);
        Vector3 sw = at.World(new Vector2(cx * size, cy * size), (float)hsw);
        Vector3 nw = at.World(new Vector2(cx * size, (cy + 1) * size), (float)hnw);
        Vector3 se = at.World(new Vector2((cx + 1) * size, cy * size), (float)hse);
        Vector3 ne = at.World(new Vector2((cx + 1) * size, (cy + 1) * size), (float)hne);
        if (terrain.IsSplitSwToNe(cx, cy))
        {
            _ = u >= v ? Emit(ref sink, sw, se, ne, id) : Emit(ref sink, sw, ne, nw, id);
        }
        else
        {
            _ = u + v <= 1.0 ? Emit(ref sink, sw, se, nw, id) : Emit(ref sink, se, ne, nw, id);
        }

        static bool Emit(ref TSink sink, Vector3 a, Vector3 b, Vector3 c, uint id)
        {
            sink.Triangle(a, b, c, DrawKind.Floor, id);
            return true;
        }
    }

    /// <summary>The support's triangle: of its cell or object, within reach of the centre, at the support's Z there.</summary>
    private static void Held<TSink>(in NearDrawing.At at, LandblockEntry entry, in Support support, Vector2 p, float reach, ref TSink sink)
        where TSink : IDebugSink
    {
        uint id = support.Floor.Id;
        foreach (CellSurface cell in entry.Cells)
        {
            if ((support.Floor.Kind == SurfaceKind.CellFloor && cell.CellId == id && Near(in at, cell.Floors, in support, p, reach, ref sink))
                || (support.Floor.Kind == SurfaceKind.ObjectFloor && Objects(in at, cell.Objects, in support, p, reach, ref sink)))
            {
                return;
            }
        }

        _ = support.Floor.Kind == SurfaceKind.ObjectFloor && Objects(in at, entry.OutdoorObjects, in support, p, reach, ref sink);
    }

    private static bool Objects<TSink>(in NearDrawing.At at, ObjectSurface[] objects, in Support support, Vector2 p, float reach, ref TSink sink)
        where TSink : IDebugSink
    {
        foreach (ObjectSurface o in objects)
        {
            if (o.ObjectId == support.Floor.Id && Near(in at, o.Floors, in support, p, reach, ref sink))
            {
                return true;
            }
        }

        return false;
    }

    private static bool Near<TSink>(in NearDrawing.At at, ReadOnlySpan<FloorTriangle> floors, in Support support, Vector2 p, float reach, ref TSink sink)
        where TSink : IDebugSink
    {
        foreach (ref readonly FloorTriangle t in floors)
        {
            if (Vector2.DistanceSquared(t.Nearest(p), p) <= (reach + Match) * (reach + Match) && MathF.Abs(t.UnderCentre(p) - support.Z) <= Match)
            {
                NearDrawing.Triangle(in at, in t, DrawKind.Support, support.Floor.Id, ref sink);
                return true;
            }
        }

        return false;
    }
}
