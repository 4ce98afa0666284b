using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.App.Movement;

/// <summary>What one <see cref="PlayerMovementMode.Update"/> did, as the engine reported it.</summary>
/// <param name="Steps">Physics steps taken (a frame, clamped to 1 s, is split into steps of at most 0.1 s): 0 for a zero-length frame, at most 10.</param>
/// <param name="RefusedSteps">Steps the engine refused (<see cref="ResolveResult.IsRefused"/>); with swept moves a step stopped part way counts.</param>
/// <param name="LastRefusal">The engine's <see cref="ResolveResult.Outcome"/> of the last refused step; null when none was refused.</param>
/// <param name="LastRefusalNormal">The engine's <see cref="ResolveResult.SurfaceNormal"/> of the last refused step (zero when the engine names no surface, or none was refused).</param>
/// <param name="SlidSteps">Steps the engine answered <see cref="ResolveOutcome.Slid"/>: the body touched a wall (or, with walkable slope, a slope too steep) and moved on along it.</param>
/// <param name="LastSlideNormal">The engine's <see cref="ResolveResult.SurfaceNormal"/> of the last slid step: a wall's unit normal (horizontal, towards the mover) or a slope's; zero when none slid.</param>
/// <param name="Met">What the engine reported the steps met (<see cref="MoveReport"/>): the floor the last step stands on, and the wall, shell or cylinder of the last step that a wall stopped or slid.</param>
/// <param name="Jumps">Jumps taken this frame (0 or 1).</param>
/// <param name="HeadHits">Steps whose rise the engine stopped under a surface (<see cref="ResolveOutcome.Ceiling"/>).</param>
/// <param name="Landings">Steps that ended on the ground after the mover was in the air.</param>
/// <param name="EdgeSlides">Steps the engine held at an edge (<see cref="ResolveOutcome.Edge"/>, or slid along a floor's edge).</param>
public readonly record struct MovementFrame(
    int Steps, int RefusedSteps, ResolveOutcome? LastRefusal, Vector3 LastRefusalNormal, int SlidSteps = 0, Vector3 LastSlideNormal = default, MoveReport Met = default,
    int Jumps = 0, int HeadHits = 0, int Landings = 0, int EdgeSlides = 0);
