using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Surfaces;

/// <summary>A box seen from above and a height band, landblock-local metres: where a call's sweeps stay.</summary>
internal readonly record struct WallBox(Vector2 Lo, Vector2 Hi, float ZLow, float ZHigh);

/// <summary>Boxes seen from above, metres.</summary>
internal static class Boxes
{
    /// <summary>
    /// Whether the closed boxes <paramref name="min"/>..<paramref name="max"/> and <paramref name="lo"/>..<paramref name="hi"/>
    /// share a point; boxes that only touch do. A point is the box from itself to itself.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Overlaps(Vector2 min, Vector2 max, Vector2 lo, Vector2 hi) =>
        min.X <= hi.X && max.X >= lo.X && min.Y <= hi.Y && max.Y >= lo.Y;
}
