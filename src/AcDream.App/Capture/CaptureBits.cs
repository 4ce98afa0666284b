using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.App.Capture;

/// <summary>
/// Whether two answers are the same bits: every float compared by its IEEE bits (so −0 is not 0), every other field by
/// value; exactly when their lines' texts (<see cref="CaptureJson.WriteAnswer"/>) are equal.
/// </summary>
internal static class CaptureBits
{
    /// <summary>Whether the recorded and the replayed answers of a call of <paramref name="kind"/> are the same bits (both null: a call with no answer, which returned).</summary>
    public static bool Same(CaptureKind kind, CaptureAnswer? recorded, CaptureAnswer? replayed)
    {
        if (recorded is null || replayed is null)
        {
            return recorded is null && replayed is null;
        }

        return kind switch
        {
            CaptureKind.RemoveMover => recorded.Removed == replayed.Removed,
            CaptureKind.RemoveMovers => recorded.Count == replayed.Count,
            CaptureKind.Commit => recorded.Commit == replayed.Commit,
            CaptureKind.Resolve => Same(recorded.Move, replayed.Move) && (recorded.Touched ?? []).AsSpan().SequenceEqual(replayed.Touched ?? []),
            CaptureKind.Cast => Same(recorded.Hit, replayed.Hit),
            _ => false,
        };
    }

    private static bool Same(in MoveResult a, in MoveResult b) =>
        Same(a.Answer.Position, b.Answer.Position) && a.Answer.CellId == b.Answer.CellId && a.Answer.IsOnGround == b.Answer.IsOnGround
        && a.Answer.Outcome == b.Answer.Outcome && Same(a.Answer.SurfaceNormal, b.Answer.SurfaceNormal)
        && Same(a.Report.Floor, b.Report.Floor) && Same(a.Report.Wall, b.Report.Wall) && a.TouchedCount == b.TouchedCount && a.Commit == b.Commit;

    private static bool Same(in CastHit a, in CastHit b) =>
        a.Hit == b.Hit && Same(a.Fraction, b.Fraction) && Same(a.Position, b.Position) && Same(a.Point, b.Point) && Same(a.Normal, b.Normal)
        && a.Kind == b.Kind && a.Id == b.Id && a.CellId == b.CellId;

    private static bool Same(in SurfaceContact a, in SurfaceContact b) => a.Kind == b.Kind && a.Id == b.Id && Same(a.Normal, b.Normal);

    private static bool Same(Vector3 a, Vector3 b) => Same(a.X, b.X) && Same(a.Y, b.Y) && Same(a.Z, b.Z);

    private static bool Same(float a, float b) => BitConverter.SingleToUInt32Bits(a) == BitConverter.SingleToUInt32Bits(b);
}
