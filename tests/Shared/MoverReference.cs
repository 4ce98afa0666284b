using System.Numerics;
using AcDream.Core.Dat;

namespace AcDream.Testing;

// Shared by the test and benchmark projects (linked, not referenced).

/// <summary>
/// Movers for the tests and the accuracy report: the game door's slab as a model, and distances to a creature's axis and
/// to a slab in double precision, independent of the engine. Metres, seen from above.
/// </summary>
internal static class MoverReference
{
    /// <summary>The game's door slab across its own frame: Y from −0.009 to 0.252 m.</summary>
    public const float SlabNear = -0.009f, SlabFar = 0.252f;

    /// <summary>A closed box X −w/2..w/2, Y <see cref="SlabNear"/>..<see cref="SlabFar"/>, Z 0..h, each face wound outward.</summary>
    public static GfxObj SlabModel(float width, float height)
    {
        float x0 = -width / 2f, x1 = width / 2f, y0 = SlabNear, y1 = SlabFar, h = height;
        return DeterminismWalk.AddPhysicsPolygons(
            new GfxObj { Id = 0x01FF0001, Flags = GfxObjFlags.HasPhysics },
            [
                [new(x0, y0, 0), new(x0, y1, 0), new(x1, y1, 0), new(x1, y0, 0)], // bottom, facing down
                [new(x0, y0, h), new(x1, y0, h), new(x1, y1, h), new(x0, y1, h)], // top (a floor: not a wall)
                [new(x0, y0, 0), new(x1, y0, 0), new(x1, y0, h), new(x0, y0, h)], // −Y
                [new(x0, y1, 0), new(x0, y1, h), new(x1, y1, h), new(x1, y1, 0)], // +Y
                [new(x0, y0, 0), new(x0, y0, h), new(x0, y1, h), new(x0, y1, 0)], // −X
                [new(x1, y0, 0), new(x1, y1, 0), new(x1, y1, h), new(x1, y0, h)], // +X
            ]);
    }

    /// <summary>A turn about Z by <paramref name="radians"/>.</summary>
    public static Quaternion Yaw(double radians) => new(0f, 0f, (float)Math.Sin(radians / 2), (float)Math.Cos(radians / 2));

    /// <summary>The distance from a point to a slab of half-width <paramref name="halfWidth"/> at <paramref name="centre"/> turned by <paramref name="yaw"/>; negative inside.</summary>
    public static double ToSlab(Vector3 point, Vector3 centre, double yaw, double halfWidth)
    {
        double dx = (double)point.X - centre.X, dy = (double)point.Y - centre.Y;
        double c = Math.Cos(yaw), s = Math.Sin(yaw);
        double u = (c * dx) + (s * dy), v = (-s * dx) + (c * dy); // into the slab's frame
        double ou = Math.Max(Math.Abs(u) - halfWidth, 0), ov = Math.Max(Math.Max(SlabNear - v, v - SlabFar), 0);
        return Math.Sqrt((ou * ou) + (ov * ov)) * (Math.Abs(u) <= halfWidth && v >= SlabNear && v <= SlabFar ? -1 : 1);
    }

    /// <summary>The distance between two points.</summary>
    public static double Apart(Vector3 a, Vector3 b) => Math.Sqrt(Math.Pow((double)a.X - b.X, 2) + Math.Pow((double)a.Y - b.Y, 2));

    /// <summary>The least distance from the segment <paramref name="a"/>..<paramref name="b"/> to the point <paramref name="c"/>.</summary>
    public static double SegmentTo(Vector3 a, Vector3 b, Vector3 c)
    {
        (double dx, double dy) = ((double)b.X - a.X, (double)b.Y - a.Y);
        double len2 = (dx * dx) + (dy * dy);
        double t = len2 == 0 ? 0 : Math.Clamp(((((double)c.X - a.X) * dx) + (((double)c.Y - a.Y) * dy)) / len2, 0, 1);
        return Math.Sqrt(Math.Pow(a.X + (t * dx) - c.X, 2) + Math.Pow(a.Y + (t * dy) - c.Y, 2));
    }
}
