using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics.Body;

// BodySweep, against walls: a cell's walls and an object's polygons, cut to the move's height band.
internal static partial class BodySweep
{
    /// <summary>
    /// Sweeps against one wall polygon (its vertices plus <paramref name="offset"/> in the move's
    /// frame), cut to the band first: the part of the polygon between the two heights, seen from above.
    /// </summary>
    [SkipLocalsInit] // the cut buffers are written before they are read
    public static void SweepPolygon(ReadOnlySpan<Vector3> vertices, Vector2 offset, in BodyMove move, ref WallHit hit)
    {
        Span<Vector3> low = stackalloc Vector3[2 * vertices.Length]; // a cut adds at most one vertex per edge
        int lowCount = Clip(vertices, low, move.ZLow, keepAbove: true);
        // Stryker disable once Statement,Block : with nothing above the band's foot, the second cut and the loop see no vertex
        if (lowCount == 0)
        {
            return;
        }

        Span<Vector3> band = stackalloc Vector3[2 * lowCount];
        int count = Clip(low[..lowCount], band, move.ZHigh, keepAbove: false);
        for (int i = 0, j = count - 1; i < count; j = i++)
        {
            var a = new Vector2(band[j].X + offset.X, band[j].Y + offset.Y);
            var b = new Vector2(band[i].X + offset.X, band[i].Y + offset.Y);
            SweepSegment(in move, a, b, 0f, ref hit);
        }
    }

    /// <summary>
    /// One cell's or object's walls (their landblock frame <paramref name="offset"/> from the move's) whose
    /// bounds meet the sweep's box (<paramref name="lo"/>–<paramref name="hi"/>, in their frame) and whose
    /// heights meet the move's band.
    /// </summary>
    public static void SweepWalls(CellWalls walls, Vector2 offset, Vector2 lo, Vector2 hi, in BodyMove move, ref WallHit hit) =>
        SweepWalls(walls, ulong.MaxValue, offset, new WallBox(lo, hi, move.ZLow, move.ZHigh), in move, ref hit);

    /// <summary>
    /// As <see cref="SweepWalls(CellWalls, Vector2, Vector2, Vector2, in BodyMove, ref WallHit)"/>, among the walls whose
    /// bits are set in <paramref name="candidates"/> (bit i: polygon i; all of them past the 64th); <paramref name="box"/>
    /// is the sweep's box and band in the walls' frame.
    /// </summary>
    public static void SweepWalls(CellWalls walls, ulong candidates, Vector2 offset, in WallBox box, in BodyMove move, ref WallHit hit)
    {
        float zLow = box.ZLow, zHigh = box.ZHigh;
        Vector2 lo = box.Lo, hi = box.Hi;
        // Stryker disable once Equality,Logical,Statement,Block : a pre-check: each wall's extent tests the box and band again
        if (!Boxes.Overlaps(walls.Min, walls.Max, lo, hi) || walls.ZMax <= zLow || walls.ZMin >= zHigh)
        {
            return;
        }

        ReadOnlySpan<WallExtent> extents = walls.Extents;
        Vector128<float> query = WallExtent.Query(lo, hi);
        // Stryker disable once Equality : with 64 walls the loop over all sweeps those the candidates would, each tested by its extent
        if (extents.Length > 64)
        {
            for (int i = 0; i < extents.Length; i++)
            {
                if (extents[i].Meets(query, zLow, zHigh))
                {
                    SweepWall(walls, i, offset, in move, ref hit);
                }
            }

            // Stryker disable once Statement : the loop below would sweep again walls swept here: the earliest contact stays
            return;
        }

        ulong left = candidates & (extents.Length == 64 ? ulong.MaxValue : (1UL << extents.Length) - 1);
        for (int n = System.Numerics.BitOperations.PopCount(left); n > 0; n--, left &= left - 1) // (a turn per bit set: the loop ends however the bits are cleared)
        {
            int i = System.Numerics.BitOperations.TrailingZeroCount(left);
            if (extents[i].Meets(query, zLow, zHigh))
            {
                SweepWall(walls, i, offset, in move, ref hit);
            }
        }
    }

    /// <summary>Sweeps polygon <paramref name="i"/> of <paramref name="walls"/>: an upright one as its segment (a cylinder's widened by its radius), another cut to the band.</summary>
    private static void SweepWall(CellWalls walls, int i, Vector2 offset, in BodyMove move, ref WallHit hit)
    {
        ref readonly WallPolygon wall = ref walls.Polygons[i];
        if (!wall.IsUpright)
        {
            SweepPolygon(walls.Vertices.AsSpan(wall.First, wall.Count), offset, in move, ref hit);
        }
        else if (wall.Radius > 0f)
        {
            // A cylinder is met at the sum of the radii, and so is its graze: the graze is measured from the contact
            // radius, else every move coming no nearer the axis than the body's own graze was taken for a graze and
            // the body walked into the trunk up to its own radius.
            WallSource owner = hit.Current;
            hit.Current = owner.Kind == SurfaceKind.Mover ? owner : owner with { Kind = SurfaceKind.Cylinder }; // (a mover is named as one)
            SweepSegment(in move, wall.A + offset, wall.B + offset, wall.Radius, ref hit);
            hit.Current = owner;
        }
        else
        {
            SweepSegment(in move, wall.A + offset, wall.B + offset, 0f, ref hit);
        }
    }

    /// <summary>Sutherland–Hodgman against the plane z = <paramref name="z"/>, keeping the side named.</summary>
    private static int Clip(ReadOnlySpan<Vector3> input, Span<Vector3> output, float z, bool keepAbove)
    {
        int count = 0;
        for (int i = 0; i < input.Length; i++)
        {
            Vector3 current = input[i], next = input[(i + 1) % input.Length];
            float dc = keepAbove ? current.Z - z : z - current.Z;
            float dn = keepAbove ? next.Z - z : z - next.Z;
            if (dc >= 0f)
            {
                output[count++] = current;
            }

            if ((dc >= 0f) != (dn >= 0f))
            {
                // Written out, not Vector3.Lerp: .NET's Lerp fuses a·(1 − s) + b·s into one multiply-add
                // where the processor has one and rounds twice where it has not, so its bits would depend
                // on the machine. These are the unfused bits, the same on every instruction set.
                float s = dc / (dc - dn), r = 1f - s;
                output[count++] = new Vector3((current.X * r) + (next.X * s), (current.Y * r) + (next.Y * s), z);
            }
        }

        return count;
    }
}
