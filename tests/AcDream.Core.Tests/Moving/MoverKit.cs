using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;

namespace AcDream.Core.Tests.Moving;

/// <summary>Movers for the tests: a creature's cylinder, a door's slab, and double-precision distances to them.</summary>
internal static class MoverKit
{
    public const float HumanRadius = 0.48f;
    public const float HumanHeight = 1.835f;

    /// <summary>The game's door slab across its own frame: Y from −0.009 to 0.252 m.</summary>
    public const float SlabNear = -0.009f, SlabFar = 0.252f;

    public static MoverShape Human { get; } = MoverShape.Cylinder(HumanRadius, HumanHeight);

    /// <summary>A closed box X −w/2..w/2, Y <see cref="SlabNear"/>..<see cref="SlabFar"/>, Z 0..h, each face wound outward.</summary>
    public static GfxObj SlabModel(float width, float height)
    {
        float x0 = -width / 2f, x1 = width / 2f, y0 = SlabNear, y1 = SlabFar, h = height;
        return ObjectKit.Gfx(
            0x01FF0001,
            [new(x0, y0, 0), new(x0, y1, 0), new(x1, y1, 0), new(x1, y0, 0)], // bottom, facing down
            [new(x0, y0, h), new(x1, y0, h), new(x1, y1, h), new(x0, y1, h)], // top (a floor: not a wall)
            [new(x0, y0, 0), new(x1, y0, 0), new(x1, y0, h), new(x0, y0, h)], // −Y
            [new(x0, y1, 0), new(x0, y1, h), new(x1, y1, h), new(x1, y1, 0)], // +Y
            [new(x0, y0, 0), new(x0, y0, h), new(x0, y1, h), new(x0, y1, 0)], // −X
            [new(x1, y0, 0), new(x1, y1, 0), new(x1, y1, h), new(x1, y0, h)]); // +X
    }

    public static Quaternion Yaw(double radians) => new(0f, 0f, (float)Math.Sin(radians / 2), (float)Math.Cos(radians / 2));

    /// <summary>The distance, seen from above, from a point to a slab of half-width <paramref name="halfWidth"/> at <paramref name="centre"/> turned by <paramref name="yaw"/> (double precision).</summary>
    public static double ToSlab(Vector3 point, Vector3 centre, double yaw, double halfWidth)
    {
        double dx = (double)point.X - centre.X, dy = (double)point.Y - centre.Y;
        double c = Math.Cos(yaw), s = Math.Sin(yaw);
        double u = (c * dx) + (s * dy), v = (-s * dx) + (c * dy); // into the slab's frame
        double ou = Math.Max(Math.Abs(u) - halfWidth, 0), ov = Math.Max(Math.Max(SlabNear - v, v - SlabFar), 0);
        return Math.Sqrt((ou * ou) + (ov * ov)) * (Math.Abs(u) <= halfWidth && v >= SlabNear && v <= SlabFar ? -1 : 1);
    }

    /// <summary>The distance seen from above between two points (double precision).</summary>
    public static double Apart(Vector3 a, Vector3 b) => Math.Sqrt(Math.Pow((double)a.X - b.X, 2) + Math.Pow((double)a.Y - b.Y, 2));
}
